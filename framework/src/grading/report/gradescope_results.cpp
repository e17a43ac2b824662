// Gradescope's results.json (grade_report.h): the class grader's per-student
// file, and the autograder's own with visibility and a report per stage.
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

namespace {

using Json = nlohmann::ordered_json;

// One test per check of a graded stage, one per stage that was not graded
// (or was graded without checks); FIELDS adds what the autograder writes.
template <typename Fields>
Json testsOf(const StudentResult& student, const Fields& fields) {
    Json tests = Json::array();
    for (std::size_t i = 0; i < student.stages.size(); ++i) {
        const StageResult& s = student.stages[i];
        if (isGraded(s) && !s.checks.empty()) {
            // Each test's maximum is the step between rounded running sums,
            // so that a stage's tests add up to its 100 points exactly (13
            // views of 70/13 points each, rounded alone, add up to 99.94).
            double before = 0;
            for (std::size_t k = 0; k < s.checks.size(); ++k) {
                const CheckResult& c = s.checks[k];
                const double max = round2(before + c.maxScore) - round2(before);
                before += c.maxScore;
                const double score = c.score >= c.maxScore ? max : std::min(round2(c.score), max);
                Json t{{"name", s.stage + " / " + c.name},
                       {"score", round2(score)},
                       {"max_score", round2(max)},
                       {"status", c.passed ? "passed" : "failed"},
                       {"output", c.output}};
                fields(t, i, k, s, &c);
                tests.push_back(std::move(t));
            }
        } else {
            bool graded = isGraded(s);
            Json t{{"name", graded ? s.stage : s.stage + ": " + statusWord(s)},
                   {"score", round2(s.score)},
                   {"max_score", round2(s.maxScore)},
                   {"status", graded && s.score >= s.maxScore ? "passed" : "failed"},
                   {"output", s.message.empty() ? statusWord(s) : s.message}};
            fields(t, i, 0, s, nullptr);
            tests.push_back(std::move(t));
        }
    }
    return tests;
}

double stageSeconds(const StudentResult& student) {
    double seconds = 0;
    for (const StageResult& s : student.stages) seconds += std::isfinite(s.seconds) ? s.seconds : 0;
    return seconds;
}

std::string dump(const Json& j) {
    // Student-controlled text may not be UTF-8: replace, never throw.
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

// When a test that is not visible now will be.
std::string whenShown(const std::string& visibility) {
    if (visibility == "after_due_date") return "after the due date";
    if (visibility == "after_published") return "when grades are published";
    return "to the course staff only";
}

}  // namespace

// ---------------------------------------------------------------- Gradescope

std::string gradescopeJson(const StudentResult& student) {
    std::string summary = "Total " + num(student.score()) + " / " + num(student.maxScore());
    for (std::size_t i = 0; i < student.stages.size(); ++i) {
        const StageResult& s = student.stages[i];
        summary += (i == 0 ? ". " : "; ") + cleanText(s.stage) + ": ";
        summary += isGraded(s) ? num(s.score) + " / " + num(s.maxScore) : statusWord(s);
    }
    Json j{{"score", round2(student.score())},
           {"execution_time", std::lround(stageSeconds(student))},
           {"output", summary},
           {"output_format", "text"},
           {"test_output_format", "text"},
           {"test_name_format", "text"},
           {"tests", testsOf(student, [](Json&, std::size_t, std::size_t, const StageResult&,
                                         const CheckResult*) {})}};
    return dump(j);
}

bool isGradescopeVisibility(const std::string& value) {
    return value == "visible" || value == "hidden" || value == "after_due_date" ||
           value == "after_published";
}

std::string gradescopeJson(const StudentResult& student, const GradescopeOptions& o) {
    auto visibilityOf = [&](const CheckResult* c) {
        return c && c->seeded ? o.seededVisibility : o.testVisibility;
    };
    Json tests = testsOf(student, [&](Json& t, std::size_t stage, std::size_t check,
                                      const StageResult& s, const CheckResult* c) {
        t["number"] = std::to_string(stage + 1) + "." + std::to_string(check + 1);
        t["tags"] = Json::array({s.stage, c ? (c->seeded            ? "seeded view"
                                               : c->kind == "image" ? "view"
                                                                    : c->kind)
                                            : "stage"});
        t["visibility"] = visibilityOf(c);
    });

    // The report per stage: only what is visible now is described.
    std::string out = o.notes;
    bool allVisible = o.testVisibility == "visible";
    for (const StageResult& s : student.stages) {
        if (!out.empty()) out += "\n";
        if (!isGraded(s)) {
            out += s.stage + ": " + statusWord(s) + " (0 / " + num(s.maxScore) + ")\n";
            if (o.testVisibility == "visible" && !s.message.empty()) out += s.message + "\n";
            continue;
        }
        int shown = 0, passed = 0;
        std::vector<std::string> later;      // "3 seeded views ... after the due date"
        std::string failures, viewFailures;  // function and count checks first: they name the input
        for (const CheckResult& c : s.checks) {
            const std::string v = visibilityOf(&c);
            if (v != "visible") {
                allVisible = false;
                later.push_back(v);
                continue;
            }
            ++shown;
            passed += c.passed ? 1 : 0;
            if (!c.passed)
                (c.kind == "image" ? viewFailures : failures) +=
                    "  " + c.name + ": " + c.output + "\n";
        }
        out += s.stage + ": " + std::to_string(passed) + " of " + std::to_string(shown) +
               " checks pass";
        if (later.empty()) out += " (" + num(s.score) + " / " + num(s.maxScore) + ")";
        out += "\n" + failures + viewFailures;
        std::sort(later.begin(), later.end());
        for (auto it = later.begin(); it != later.end();) {
            auto end = std::upper_bound(it, later.end(), *it);
            const long count = long(end - it);
            out += "  " + std::to_string(count) +
                   (count == 1 ? " more check is" : " more checks are") + " shown " +
                   whenShown(*it) + "\n";
            it = end;
        }
    }
    out = (allVisible ? "Total " + num(student.score()) + " / " + num(student.maxScore())
                      : std::string("The total appears when every test is shown")) +
          "\n\n" + out;

    Json j{{"score", round2(student.score())},
           {"execution_time", std::lround(o.seconds >= 0 ? o.seconds : stageSeconds(student))},
           // Said explicitly, and plain text everywhere: compiler messages hold
           // '<' and '&', shown as they are (no markup to escape).
           {"output", cleanText(out)},
           {"output_format", "text"},
           {"test_output_format", "text"},
           {"test_name_format", "text"},
           {"visibility", o.visibility},
           {"stdout_visibility", o.stdoutVisibility},
           {"tests", std::move(tests)}};
    return dump(j);
}

void writeGradescopeResults(const StudentResult& student, const fs::path& file) {
    writeTextFileAtomic(file, gradescopeJson(student));
}

}  // namespace raylab
