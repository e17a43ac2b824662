#pragma once
// Where a stage's shader files are read from.
//  - the solution of stage N: solution/N/, then the solutions of the earlier
//    stages (a later stage may replace an earlier file), then framework/shaders/;
//  - a lab: LAB/N/ (a folder laid out like labs/, e.g. a student's copy), then
//    framework/shaders/. Labs are self-contained: labs/N/ already holds the
//    earlier stages' files, solved.
#include "stage_catalog.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct StageSources {
    std::vector<std::filesystem::path> search;
    std::string label;  // "solution" or "lab labs/"
};

StageSources solutionSources(const StageInfo& stage);

// Throws Error when LABROOT or LABROOT/<stage> is missing.
StageSources labSources(const StageInfo& stage, const std::filesystem::path& labRoot);

// labs/ of the project.
std::filesystem::path defaultLabRoot();

} // namespace raylab
