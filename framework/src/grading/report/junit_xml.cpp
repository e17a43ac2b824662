// JUnit XML for CI dashboards (grade_report.h).
#include "grade_report.h"

#include "atomic_file.h"
#include "report_text.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

using namespace report;
namespace fs = std::filesystem;

// ---------------------------------------------------------------- JUnit

std::string junitXml(const ClassResult& r) {
    struct Counts {
        int tests = 0, failures = 0, errors = 0;
    };
    auto attr = [](const std::string& s) { return escapeMarkup(s, true); };
    auto seconds = [](double v) { return fixedPoint(std::isfinite(v) && v > 0 ? v : 0.0, 3); };

    std::string suites;
    Counts all;
    for (const StudentResult& st : r.students) {
        Counts c;
        double time = 0;
        std::string cases;
        for (const StageResult& s : st.stages) {
            time += std::isfinite(s.seconds) ? s.seconds : 0;
            const std::string classname = attr(st.name + "." + s.stage);
            if (isGraded(s) && !s.checks.empty()) {
                for (const CheckResult& k : s.checks) {
                    ++c.tests;
                    cases += "    <testcase classname=\"" + classname + "\" name=\"" +
                             attr(k.name) + "\"";
                    if (k.passed) {
                        cases += "/>\n";
                        continue;
                    }
                    ++c.failures;
                    cases += ">\n      <failure message=\"" + attr(firstLine(k.output)) +
                             "\" type=\"" + attr(k.kind) + "\">" +
                             escapeMarkup("score " + num(k.score) + " / " + num(k.maxScore) +
                                          (k.output.empty() ? "" : ": " + k.output)) +
                             "</failure>\n    </testcase>\n";
                }
                continue;
            }
            ++c.tests;
            cases += "    <testcase classname=\"" + classname + "\" name=\"stage\" time=\"" +
                     seconds(s.seconds) + "\"";
            const std::string text = escapeMarkup(s.message.empty() ? statusWord(s) : s.message);
            if (isGraded(s) && s.score >= s.maxScore) {
                cases += "/>\n";
            } else if (isGraded(s) || s.status == "not submitted") {
                ++c.failures;
                cases += ">\n      <failure message=\"" +
                         attr(isGraded(s) ? "score " + num(s.score) + " / " + num(s.maxScore)
                                          : statusWord(s)) +
                         "\" type=\"" + attr(statusWord(s)) + "\">" + text +
                         "</failure>\n    </testcase>\n";
            } else {
                ++c.errors;
                cases +=
                    ">\n      <error message=\"" +
                    attr(statusWord(s) + (s.message.empty() ? "" : ": " + firstLine(s.message))) +
                    "\" type=\"" + attr(statusWord(s)) + "\">" + text +
                    "</error>\n    </testcase>\n";
            }
        }
        suites += "  <testsuite name=\"" + attr(st.name) + "\" tests=\"" + std::to_string(c.tests) +
                  "\" failures=\"" + std::to_string(c.failures) + "\" errors=\"" +
                  std::to_string(c.errors) + "\" skipped=\"0\" time=\"" + seconds(time) + "\"";
        suites += cases.empty() ? "/>\n" : ">\n" + cases + "  </testsuite>\n";
        all.tests += c.tests;
        all.failures += c.failures;
        all.errors += c.errors;
    }
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"raylab grade\" "
           "tests=\"" +
           std::to_string(all.tests) + "\" failures=\"" + std::to_string(all.failures) +
           "\" errors=\"" + std::to_string(all.errors) + "\" time=\"" + seconds(r.seconds) +
           "\">\n" + suites + "</testsuites>\n";
}

void writeJunitXml(const ClassResult& result, const fs::path& file) {
    writeTextFileAtomic(file, junitXml(result));
}

}  // namespace raylab
