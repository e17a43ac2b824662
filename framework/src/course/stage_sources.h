#pragma once
// Where a stage's shader files are read from.
//  - the solution of stage N: solution/N/, then the solutions of the stages
//    it builds on (a later stage may replace an earlier file), then
//    framework/shaders/;
//  - a lab: LAB/N/ (a folder laid out like labs/, e.g. a student's copy), then
//    framework/shaders/. Labs are self-contained: labs/N/ already holds the
//    earlier stages' files, solved.
// Shader variants (the textbook numerics, the seed's torus solver, the
// linear search) are whole files under framework/shaders/variants/, put in
// front of the stage file they replace when their switch is on, so that the
// files students read hold no switches of the framework's.
#include "stage_catalog.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct StageSources {
    std::vector<std::filesystem::path> search;
    std::string label;               // "solution" or "lab labs/"
    std::vector<std::string> chain;  // the stage and those it builds on, newest first
    bool lab = false;                // search[0] holds the whole chain's files
};

// SOURCES' search path with the variant folders that DEFINES switch on
// (framework/shaders/variants/<variant>/<stage id>/) in front of the stage
// folders whose files they replace.
std::vector<std::filesystem::path> searchWithVariants(const StageSources& sources,
                                                      const std::vector<std::string>& defines);

StageSources solutionSources(const StageInfo& stage);

// Throws Error when LABROOT or LABROOT/<stage> is missing.
StageSources labSources(const StageInfo& stage, const std::filesystem::path& labRoot);

// labs/ of the project.
std::filesystem::path defaultLabRoot();

}  // namespace raylab
