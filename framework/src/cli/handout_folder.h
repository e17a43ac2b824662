#pragma once
// Writing a handout's folders (`raylab handout`, and the labs of `raylab
// web-bundle`): each released stage's folder with its guide, pictures and
// the shader files the plan names (course/handout.h), and a README.md listing
// them.
#include "course_file.h"
#include "handout.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

// Throws Error naming the first file of PLAN that LABS lacks.
void checkHandoutSources(const std::vector<HandoutStage>& plan, const std::filesystem::path& labs);

// Writes PLAN's stage folders from LABS into TO (which must exist).
// LABFOLDER: how the guides' commands name the folder ("week3/"; empty:
// leave them alone). Throws std::filesystem::filesystem_error or Error.
void writeHandoutFolder(const std::vector<HandoutStage>& plan, const std::filesystem::path& labs,
                        const std::filesystem::path& to, const std::string& labFolder,
                        const CourseSettings& course);

}  // namespace raylab
