#pragma once
// What grading found, for one check, one stage of one student, one student
// and the whole class. Filled in by the grader (grading/grade_*.cpp), written
// out by the report writers of this folder (grade_report.h: HTML, Gradescope
// JSON, CSV, JUnit XML).
#include <string>
#include <vector>

namespace raylab {

struct CheckResult {
    std::string name;  // "front", "seeded-2", "intersectSphere"
    std::string kind;  // "image" or "function"
    double score = 0;  // 0..maxScore (partial credit)
    double maxScore = 0;
    bool passed = false;  // full marks
    // What the check measured, 0..1: the share of pixels that differ (an
    // image check) or of cases or views that disagree (a function or count
    // check). The credit curves of stage_grading.h turn it into the score.
    double difference = 0;
    // An image check from a view drawn from the seed (grade_views.h): the
    // views students never see in `raylab check`, which a course may keep
    // hidden until after the due date (Gradescope's visibility).
    bool seeded = false;
    std::string output;  // one line: what was measured, why it failed ("3.1% of pixels differ (max
                         // 255/255)")
    // Image checks: paths relative to the output folder, empty when not available.
    std::string studentImage, referenceImage, diffImage;
};

struct StageResult {
    std::string stage;  // "04-recursion"
    // "graded", "not submitted", "compile error", "timed out", "crashed",
    // "out of memory", "error" (anything else). NaN/Inf pixels do not change
    // the status: they score the image check 0.
    std::string status;
    std::string message;  // for anything but "graded": the reason, e.g. the compiler log mapped to
                          // file:line
    double score = 0;
    double maxScore = 100;
    double seconds = 0;  // wall time of the child process
    // The most memory the child held (MB): for `raylab grade --estimate`,
    // measured in this run only, not kept in result.json.
    double peakMb = 0;
    std::vector<CheckResult> checks;
    // A course's late policy (course_file.h): the points it took (score is
    // what is left) and why ("submitted 2026-12-12 09:10 UTC, 2 days late:
    // -20%"); 0 and empty when on time or without a policy.
    double latePenalty = 0;
    std::string lateNote;
    // Excused by the course file (course_file.h, "excused"): neither its
    // score nor its points count, whatever was graded; excuseNote says why.
    bool excused = false;
    std::string excuseNote;
    double rawScore() const { return score + latePenalty; }
};

// One row of the roster an instructor gives (`raylab grade --roster`): the
// student's id and what an LMS import needs. Empty fields: not given.
struct RosterEntry {
    std::string id;        // the student's id (SIS User ID in Canvas)
    std::string fullName;  // as the LMS shows it ("Last, First")
    std::string canvasId;  // Canvas's own user id ("ID")
    std::string loginId;   // SIS Login ID; the username in Moodle, Blackboard and Brightspace
    std::string section;
    std::string email;  // Moodle can match students by it
};

// One regrade of a student (`raylab grade --only NAME`): when, why (as the
// instructor gave it), and each stage whose result changed.
struct RegradeChange {
    std::string stage;
    std::string before, after;  // "70", "compile error"
};
struct Regrade {
    std::string when;    // "2026-12-07 09:14 UTC"
    std::string reason;  // --reason; may be empty
    std::vector<RegradeChange> changes;
};

struct StudentResult {
    std::string name;  // the submission folder's name (a pseudonym with --anonymise)
    std::vector<StageResult> stages;
    RosterEntry roster;             // empty without a roster (or with --anonymise)
    bool hasFolder = true;          // false: in the roster, but no submission folder
    std::vector<Regrade> regrades;  // oldest first
    double score() const;           // excused stages left out
    double maxScore() const;
};

// A catalogued mistake (tests/mistakes/<stage>/*.json) and how many graded
// stages failed exactly the checks it fails (report.html's class summary).
// One row of the report's known mistakes: a catalogued mistake, or several
// that fail the same checks and whose hints name the same causes (a report
// cannot tell them apart: they share one row, "name-a, name-b").
struct MistakeMatch {
    std::string stage, name;          // "03-shadows", "fixed-offset"
    std::string description;          // the catalogue's "mistake" ("...; or ..." for several)
    bool central = false;             // the stage's skill (any of them)
    std::vector<std::string> checks;  // the checks it fails (its "caught_by")
    int matches = 0;
    std::vector<std::string> hints;  // the causes its hints name (its "hints")
};

struct ClassResult {
    std::vector<std::string> stages;  // graded stage ids, in order
    std::vector<StudentResult> students;
    std::vector<MistakeMatch> mistakes;  // of the graded stages; empty: no catalogue
    unsigned seed = 0;                   // of the seeded camera poses
    bool anonymised = false;             // names are pseudonyms (raylab grade --anonymise)
    // The course file whose weights the scores were computed under, as a
    // digest of its text ("" for stage.json's own): shares and regrades
    // under other weights are refused.
    std::string courseDigest;
    std::string machine;  // e.g. "OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe"
    double seconds = 0;   // wall time of the whole run
};

}  // namespace raylab
