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

// Gradescope's results.json: {"score", "execution_time", "output", the
// formats of the output, the tests' outputs and names (all "text": plain
// text, shown as it is), "tests": [
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

// student,id,<stage ids...>,total,max,notes - one row per student in
// ClassResult order. id: the roster's (empty without one). Stage columns
// hold the score after any late penalty (empty when the student did not
// submit the stage); notes lists the stages that were not graded
// ("04-recursion: compile error") and the late ones ("03-shadows: submitted
// ..., 2 days late: -20% (72 of 90)"). CRLF line ends.
std::string summaryCsv(const ClassResult& result);
void writeSummaryCsv(const ClassResult& result, const std::filesystem::path& file);

// Canvas's gradebook import (Grades > Import): Student, ID, SIS User ID,
// SIS Login ID, Section, then one column per stage named "PREFIX<stage id>"
// (Canvas makes a new assignment of each name it does not know), a "Points
// Possible" row, then one row per roster student with an id Canvas can match
// (ID, SIS User ID or SIS Login ID). Scores after late penalties; a stage not
// submitted is left empty, which Canvas leaves as it is. Throws Error when
// no student has an id.
std::string canvasCsv(const ClassResult& result, const std::string& prefix);
void writeCanvasCsv(const ClassResult& result, const std::filesystem::path& file,
                    const std::string& prefix);

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
