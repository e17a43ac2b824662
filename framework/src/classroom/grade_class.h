#pragma once
// Grading a class's submissions: every stage of every submission in a child
// process of its own (`raylab grade-item`, cli/cmd_grade_item.cpp) with a
// timeout and a memory limit, --jobs at a time, with a progress line; one
// bad submission never stops the run or touches another's score.
#include "grade_options.h"
#include "grade_result.h"
#include "stage_catalog.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

// Grades the class G describes (its --shard share, if any) into G.outDir's
// students/ and reference/ folders; nullopt when interrupted (Ctrl-C).
// The reports are written by class_reports.h; the single-submission graders
// (upload_grading.h) write their own results.
std::optional<ClassResult> gradeClass(const GradeOptions& g);

// The student folders in SUBMISSIONS, sorted. Symbolic links are skipped (a
// link could lead anywhere, also to the solution) and said so. Throws Error
// when there is no such folder or no student in it.
std::vector<std::string> studentFolders(const std::filesystem::path& submissions);

// What a whole run writes in OUT (and clears first: no stale result of an
// earlier run may be mixed into this one), shard.json aside.
std::vector<std::string> classOutputs();

// The stages --stages names ("01-03,f1"); every stage when LIST is empty.
std::vector<const StageInfo*> stagesToGrade(const std::string& list);

}  // namespace raylab
