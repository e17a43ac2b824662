// Gradescope's results.json (grade_report.h).
#include "grade_report.h"

#include "atomic_file.h"
#include "report_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

using namespace report;
namespace fs = std::filesystem;

// ---------------------------------------------------------------- Gradescope

std::string gradescopeJson(const StudentResult& student) {
    using Json = nlohmann::ordered_json;
    Json tests = Json::array();
    std::string summary = "Total " + num(student.score()) + " / " + num(student.maxScore());
    double seconds = 0;
    for (std::size_t i = 0; i < student.stages.size(); ++i) {
        const StageResult& s = student.stages[i];
        seconds += std::isfinite(s.seconds) ? s.seconds : 0;
        summary += (i == 0 ? ". " : "; ") + cleanText(s.stage) + ": ";
        summary += isGraded(s) ? num(s.score) + " / " + num(s.maxScore) : statusWord(s);
        if (isGraded(s) && !s.checks.empty()) {
            for (const CheckResult& c : s.checks) {
                tests.push_back(Json{{"name", s.stage + " / " + c.name},
                                     {"score", round2(c.score)},
                                     {"max_score", round2(c.maxScore)},
                                     {"status", c.passed ? "passed" : "failed"},
                                     {"output", c.output}});
            }
        } else {
            // Not graded (or graded without checks): the stage as one test.
            bool graded = isGraded(s);
            tests.push_back(Json{{"name", graded ? s.stage : s.stage + ": " + statusWord(s)},
                                 {"score", round2(s.score)},
                                 {"max_score", round2(s.maxScore)},
                                 {"status", graded && s.score >= s.maxScore ? "passed" : "failed"},
                                 {"output", s.message.empty() ? statusWord(s) : s.message}});
        }
    }
    Json j{{"score", round2(student.score())},
           {"execution_time", std::lround(seconds)},
           {"output", summary},
           {"tests", std::move(tests)}};
    // Student-controlled text may not be UTF-8: replace, never throw.
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void writeGradescopeResults(const StudentResult& student, const fs::path& file) {
    writeTextFileAtomic(file, gradescopeJson(student));
}

}  // namespace raylab
