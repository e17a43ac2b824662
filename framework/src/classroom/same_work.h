#pragma once
// Grading each piece of work once. Two submissions of a stage whose files
// are the same - the stage folder, and the earlier stage folders of the
// student's that it reads (stage_sources.h) - get the same verdict: the
// renders and checks are deterministic. A class graded every week holds many
// such items (the stages not yet started are the handout as given), so
// `raylab grade` grades one of them and gives its result to the others
// (grade_class.cpp), their pictures copied into their own folders.
#include "grade_result.h"
#include "stage_catalog.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

// A digest (BLAKE2b) of what grading STAGE reads from the lab in LABROOT:
// the names and contents of the files in LABROOT/<stage>/ and in the
// earlier stage folders it reads. None when that cannot be told safely (a
// link in a folder, a file that cannot be read, sources that do not
// resolve): that item is graded on its own.
std::optional<std::string> sameWorkKey(const StageInfo& stage,
                                       const std::filesystem::path& labRoot);

// LEADER, graded into OUT/students/<FROM>/<stage>/, as the result of the
// same work by the student shown as TO: its pictures copied into TO's
// folder and its image paths moved there, its time and memory 0 (no child
// ran for it). None, and nothing written, when
// the result's texts or its log name the leader (NAMES: its folder's name
// and how it is shown; a compiler's message names the file's folder): then
// that student is graded on their own.
std::optional<StageResult> copySameWork(const StageResult& leader, const std::filesystem::path& out,
                                        const std::string& from, const std::string& to,
                                        const std::vector<std::string>& names);

}  // namespace raylab
