#pragma once
// Writes grading results (grade_result.h) out in the formats instructors and
// their tools read:
//   - Gradescope autograder results.json, one per student;
//   - a class summary CSV (RFC 4180) for spreadsheets;
//   - JUnit XML for CI dashboards;
//   - HTML pages: the class's, and one per student with every stage and check.
// All output is deterministic (no dates, no hash-order): the same results give
// byte-identical files. Scores are rounded to 2 decimals. Every writer goes
// through writeTextFileAtomic, so a result file is either complete or absent.
#include "grade_result.h"

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

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

// The LMS gradebook imports, one row per roster student the LMS can match,
// scores after late penalties, a stage not submitted left empty (each LMS
// then leaves that grade as it is). Each throws Error when no student has an
// id that LMS matches by. COLUMNS: each stage's column is PREFIX<stage id>;
// IDS gives the LMS's own id of a stage's column where the course file has it.
struct GradebookColumns {
    std::string prefix = "RayLab ";
    std::map<std::string, std::string> ids;  // stage id -> the LMS's column id
};
// Canvas (Grades > Import): Student, ID, SIS User ID, SIS Login ID, Section,
// a column per stage ("RayLab 01-raycast (87568490)" with its assignment's
// id), a "Points Possible" row; "EX" for an excused stage.
std::string canvasCsv(const ClassResult& result, const GradebookColumns& columns);
// Moodle (Grades > Import > CSV file): First name, Last name, ID number,
// Email address, Username (map one of them to the user), a column per stage.
std::string moodleCsv(const ClassResult& result, const GradebookColumns& columns);
// Blackboard Learn (Grade Center > Work Offline > Upload): "Last Name",
// "First Name", "Username", "Student ID", a column per stage ("RayLab
// 01-raycast [Total Pts: 100 Score] |1234" with its column's id), every
// field quoted; matched by username.
std::string blackboardCsv(const ClassResult& result, const GradebookColumns& columns);
// Brightspace (Grades > Enter Grades > Import): OrgDefinedId, Username
// ("#"-prefixed), "RayLab 01-raycast Points Grade" per stage, End-of-Line
// Indicator ("#").
std::string brightspaceCsv(const ClassResult& result, const GradebookColumns& columns);

// regrades.csv: when,student,reason,stage,before,after - a row per stage a
// regrade changed (one with empty stage columns when it changed nothing),
// students in ClassResult order, each student's regrades oldest first.
std::string regradeCsv(const ClassResult& result);

// <testsuites> with one <testsuite name=STUDENT> per student and one
// <testcase classname="STUDENT.STAGE" name=CHECK> per check (<failure> when
// not passed). A stage that was not graded is one testcase named "stage":
// <failure> for "not submitted", <error> for anything else (compile error,
// timeout, crash...), with the message as text.
std::string junitXml(const ClassResult& result);
void writeJunitXml(const ClassResult& result, const std::filesystem::path& file);

// The HTML report, in pages that scale to a class of hundreds:
//  - the class's page (OUTDIR/report.html): the class at a glance (the
//    checks that fail most, the catalogued mistakes the failures look like,
//    each listed once), then one row per student (section, each stage's
//    score or status, the total), sortable by any column, every row linking
//    to the student's page; no pictures, so that it stays small;
//  - a page per student (OUTDIR/students/<name>/report.html): every stage
//    with its checks, its pictures beside the reference's (loaded lazily,
//    the alt text saying whose picture of which stage and view), compiler
//    messages, late and excused notes, the regrades.
// Inline CSS, no external resources; the only script sorts the class table.
// Image paths of the checks are relative to OUTDIR.
struct ClassPageOptions {
    std::string title = "RayLab grading report";
    // Links to the sections' own reports: (section, path relative to OUTDIR).
    std::vector<std::pair<std::string, std::string>> sections;
};
std::string htmlClassPage(const ClassResult& result, const ClassPageOptions& options = {});
std::string htmlStudentPage(const ClassResult& result, const StudentResult& student);
void writeHtmlReport(const ClassResult& result, const std::filesystem::path& outDir,
                     const ClassPageOptions& options = {});

}  // namespace raylab
