#pragma once
// Writing a handout's folders (`raylab handout`, and the labs of `raylab
// web-bundle`): each released stage's folder with its guide, pictures and
// the shader files the plan names (course/handout.h), and a README.md listing
// them.
#include "course_file.h"
#include "handout.h"
#include "lab_folder.h"
#include "lab_markers.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace raylab {

// Throws Error naming the first file of PLAN that LABS lacks.
void checkHandoutSources(const std::vector<HandoutStage>& plan, const std::filesystem::path& labs);

// Writes PLAN's stage folders from LABS into TO (which must exist).
// LABFOLDER: how the guides' commands name the folder ("week3/"; empty:
// leave them alone). At the open level a stage's own files and its guide
// are generated from solution/ (lab_folder.h); LABS gives the pictures and
// the earlier stages' solved files. SOLUTION LeaveOut: the guides without
// what needs the solution (a student repository: lab_folder.h). Throws
// std::filesystem::filesystem_error or Error.
void writeHandoutFolder(const std::vector<HandoutStage>& plan, const std::filesystem::path& labs,
                        const std::filesystem::path& to, const std::string& labFolder,
                        const CourseSettings& course, Level level = Level::Guided,
                        SolutionText solution = SolutionText::Keep);

// --out OUTDIR as a folder to write: a name ("week3/" is week3), new or
// empty, in a folder that exists. Throws Error("--out ...: why").
std::filesystem::path newOutputFolder(const std::string& outDir);

// OUT appears whole or not at all: WRITE fills a temporary folder beside it,
// which is then renamed to OUT (an empty OUT is replaced). WHAT names the
// folder in errors ("the handout").
void writeWhole(const std::filesystem::path& out, const std::string& what,
                const std::function<void(const std::filesystem::path&)>& write);

}  // namespace raylab
