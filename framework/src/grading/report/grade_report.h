#pragma once
// Writes grading results (grade_result.h) out in the formats instructors and
// their tools read:
//   - Gradescope autograder results.json, one per student;
//   - a class summary CSV (RFC 4180) for spreadsheets;
//   - JUnit XML for CI dashboards;
//   - one self-contained HTML page with every student, stage and check.
// All output is deterministic (no dates, no hash-order): the same results give
// byte-identical files. Scores are rounded to 2 decimals. Every writer goes
// through writeTextFileAtomic, so a result file is either complete or absent.
#include "grade_result.h"

#include <filesystem>
#include <string>

namespace raylab {

// Gradescope's results.json: {"score", "execution_time", "output", "tests": [
// {"name": "STAGE / CHECK", "score", "max_score", "status": "passed"|"failed",
// "output"}]}. One test per check of a graded stage, one per stage that was
// not graded ("04-recursion: compile error", output = the message), so the
// tests' max_score add up to the student's maxScore().
std::string gradescopeJson(const StudentResult& student);
void writeGradescopeResults(const StudentResult& student, const std::filesystem::path& file);

// The same for Gradescope's autograder itself (`raylab gradescope`): every
// test also gets its "visibility", a "number" ("2.3": stage 2, check 3) and
// "tags" (the stage, the kind of check), and the top-level "output" is a
// readable report per stage (what failed and how, the compiler messages with
// file:line, the hints) of what students may see now: a check shown only
// later is counted there, never described, and the total is left out while
// any test is hidden (Gradescope hides it then too). Visibility values are
// Gradescope's: "visible", "hidden", "after_due_date", "after_published".
struct GradescopeOptions {
    std::string visibility = "visible";               // the submission as a whole
    std::string testVisibility = "visible";           // every test but the seeded views'
    std::string seededVisibility = "after_due_date";  // the seeded views (CheckResult::seeded)
    std::string stdoutVisibility = "hidden";          // the autograder's own log
    std::string notes;    // first lines of the output (files left out of the upload)
    double seconds = -1;  // execution_time; negative: the stages' own times
};
std::string gradescopeJson(const StudentResult& student, const GradescopeOptions& options);
bool isGradescopeVisibility(const std::string& value);

// student,<stage ids...>,total,max,notes - one row per student in ClassResult
// order. Stage columns hold the score (numeric, empty when the student has no
// result for the stage); notes lists the stages that were not graded
// ("04-recursion: compile error; 05-x: not submitted"). CRLF line ends.
std::string summaryCsv(const ClassResult& result);
void writeSummaryCsv(const ClassResult& result, const std::filesystem::path& file);

// <testsuites> with one <testsuite name=STUDENT> per student and one
// <testcase classname="STUDENT.STAGE" name=CHECK> per check (<failure> when
// not passed). A stage that was not graded is one testcase named "stage":
// <failure> for "not submitted", <error> for anything else (compile error,
// timeout, crash...), with the message as text.
std::string junitXml(const ClassResult& result);
void writeJunitXml(const ClassResult& result, const std::filesystem::path& file);

// OUTDIR/report.html: one page, inline CSS, no script, no external resources.
// Image paths of the checks are relative to OUTDIR and used as they are.
std::string htmlReport(const ClassResult& result);
void writeHtmlReport(const ClassResult& result, const std::filesystem::path& outDir);

}  // namespace raylab
