#pragma once
// Grading one stage of one submission, inside the child process that
// `raylab grade` starts for it (cmd_grade_item.cpp). Also renders the
// solution's images that every submission is compared with.
//
// Points (documented for students in every labs/<stage>/README.md, "How you
// are graded", generated from the same data by raylab-labgen):
//   - a stage is worth 100 points, shared among its checks by the weights of
//     its grading (stage_grading.h: stage.json's "grading", or a course
//     file's);
//   - a check's credit falls continuously with what it measured
//     (viewCredit, caseCredit); a view with NaN or Inf pixels earns nothing;
//   - a picture still equal to the lab as handed out (labs/<stage>) earns
//     nothing, and a view the handed-out lab already draws right (it never
//     reaches the stage's code) earns at most the share of their points the
//     other views earned, so an untouched lab scores 0.
#include "grade_result.h"
#include "stage_catalog.h"
#include "stage_sources.h"

#include <filesystem>

namespace raylab {

// Where one student's results go: OUT/students/<name>/ (never next to the
// class files, whatever the student's folder is called).
inline std::filesystem::path studentFolder(const std::filesystem::path& outDir,
                                           const std::string& student) {
    return outDir / "students" / student;
}

inline constexpr int kGradeWidth = 160;
inline constexpr int kGradeHeight = 120;

// OUT/reference/<stage>/<view>.png for every grading view (solution, float
// target converted to 8 bits exactly as for submissions), and the lab as
// handed out from the same views in OUT/reference/<stage>/untouched/.
void renderGradingReferences(const StageInfo& stage, unsigned seed,
                             const std::filesystem::path& outDir);

// Grades LABROOT/<stage>/ against OUT/reference/<stage>/; writes the
// student's images and diff heat maps to OUT/students/<student>/<stage>/. A compile
// error gives status "compile error" with the log mapped to file:line.
// EARLIER: where the earlier stages' files come from (stage_sources.h); with
// Solved, a student's own earlier file that fails its stage's function check
// and that this stage would read is named in the result's message.
StageResult gradeStage(const StageInfo& stage, const StageGrading& grading,
                       const std::filesystem::path& labRoot, const std::string& student,
                       const std::filesystem::path& outDir, unsigned seed,
                       EarlierStages earlier = EarlierStages::Solved);

// StageResult <-> JSON, for the child to hand its result to the parent.
std::string stageResultToJson(const StageResult& result);
StageResult stageResultFromJson(const std::string& text);  // throws Error on malformed input

}  // namespace raylab
