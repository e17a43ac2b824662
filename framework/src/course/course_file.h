#pragma once
// A course's own settings for grading (`raylab grade --course FILE`): the
// stages' weights where the course wants others than stage.json's, and a late
// policy. JSON, every key optional; unknown keys are errors (a typo must not
// fall back to a default):
//
//   {
//     "earlier_stages": "solved",
//     "stages": {
//       "03-shadows": {"grading": {"views": 40, "weights": {"lightVisible": 2}}}
//     },
//     "late": {
//       "deadline": "2026-12-10T23:59:00+01:00",
//       "deadlines": {"03-shadows": "2026-12-17T23:59:00+01:00"},
//       "grace_minutes": 15,
//       "penalty_per_day": 10,
//       "max_penalty": 50
//     },
//     "extensions": [
//       {"student": "bob", "stages": "03", "days": 2, "reason": "ill, note of 12 Dec"},
//       {"student": "carol", "until": "2026-12-20T12:00:00Z"}
//     ],
//     "excused": [{"student": "dave", "stages": "02", "reason": "exchange week"}],
//     "lms": {
//       "column_prefix": "RayLab ",
//       "canvas_assignments": {"01-raycast": 87568490},
//       "blackboard_columns": {"01-raycast": 1234}
//     }
//   }
//
// "extensions" move one student's deadlines (for "stages", default every
// stage): "days" later, or "until" a time; the late policy then counts from
// there. "excused" stages count for nothing, neither score nor points (an
// LMS that knows "excused" is told so). "student" is the submission
// folder's name, as in the roster. "lms" names the gradebook columns the
// exports write (`raylab grade --lms`): Canvas matches a column to its
// assignment by the assignment's id, Blackboard by the column's id; without
// one, each LMS makes a new column named by the prefix and the stage id.
//
// "earlier_stages" says where a stage's grading takes the earlier stages it
// builds on from (stage_sources.h): "solved" (the default: the course's
// solutions, so a slip in 01 costs points in 01 only, each stage graded on
// its own work) or "own" (the student's own earlier stage folders, as
// `raylab check` draws them: a stage is graded on what it really draws, but
// one slip in 01 is paid again in 02, 03, ...). A submission of one stage
// folder alone is graded the same either way.
//
// "grading" is stage.json's (stage_grading.h), over the stage's own: what it
// sets replaces, the rest stays. The late policy takes penalty_per_day percent
// of the score a stage earned for every day or part of a day past its deadline (after
// the grace minutes), at most max_penalty percent; a stage without a deadline
// is never late. Times are ISO 8601 with a zone: "2026-12-10T23:59:00Z",
// "2026-12-10T23:59+01:00".
#include "stage_catalog.h"
#include "stage_sources.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

struct LatePolicy {
    std::optional<std::int64_t> deadline;           // Unix seconds, every stage
    std::map<std::string, std::int64_t> deadlines;  // stage id -> its own
    double graceMinutes = 0;
    double penaltyPerDay = 0;  // percent of the score the stage earned
    double maxPenalty = 100;   // percent
    std::optional<std::int64_t> deadlineOf(const std::string& stage) const;
    // Whole days (or parts) past the deadline; 0 when on time or no deadline.
    int daysLate(const std::string& stage, std::int64_t submitted) const;
    int daysLate(std::optional<std::int64_t> due, std::int64_t submitted) const;
    // The percent of the earned score taken for DAYS late.
    double penaltyPercent(const std::string& stage, std::int64_t submitted) const;
    double penaltyForDays(int days) const;
};

// One student's extension or excused stages (the course file's
// "extensions" and "excused").
struct StudentException {
    std::string student;              // the submission folder's name
    std::vector<std::string> stages;  // stage ids; empty: every stage
    std::int64_t extraSeconds = 0;    // "days" later
    std::optional<std::int64_t> until;
    std::string reason;
    bool covers(const std::string& student, const std::string& stage) const;
};

// The gradebook columns of the LMS exports.
struct LmsColumns {
    std::string prefix = "RayLab ";
    std::map<std::string, std::string> canvasAssignments;  // stage id -> Canvas assignment id
    std::map<std::string, std::string> blackboardColumns;  // stage id -> Grade Center column id
};

struct CourseSettings {
    std::filesystem::path file;                   // empty: no course file
    std::map<std::string, StageGrading> grading;  // stage id -> the course's
    std::optional<LatePolicy> late;
    EarlierStages earlierStages = EarlierStages::Solved;
    std::vector<StudentException> extensions, excused;
    LmsColumns lms;
    // STUDENT's deadline for STAGE: the late policy's, moved by an extension.
    std::optional<std::int64_t> deadlineFor(const std::string& student,
                                            const std::string& stage) const;
    const StudentException* extensionOf(const std::string& student, const std::string& stage) const;
    const StudentException* excuseOf(const std::string& student, const std::string& stage) const;
    // The stage's grading: the course's where it sets one, else stage.json's.
    const StageGrading& gradingOf(const StageInfo& stage) const;
};

// Throws Error("FILE: KEY: why").
CourseSettings readCourseFile(const std::filesystem::path& file);

// What a course file adds to STAGE's "How you are graded" in a handout (a
// deadline and the late policy, where the earlier stages come from): empty
// for a course file that sets none of them, or none at all.
std::string courseRulesSection(const StageInfo& stage, const CourseSettings& course);

// "2026-12-10T23:59:00+01:00" (seconds optional, "Z" or +-HH:MM required) ->
// Unix seconds. Throws Error("WHERE: ...").
std::int64_t parseIsoTime(const std::string& text, const std::string& where);
// Unix seconds -> "2026-12-10 22:59 UTC".
std::string formatUtc(std::int64_t seconds);

}  // namespace raylab
