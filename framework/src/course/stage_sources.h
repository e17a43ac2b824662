#pragma once
// Where a stage's shader files are read from.
//  - the solution of stage N: solution/N/, then the solutions of the stages
//    it builds on (a later stage may replace an earlier file), then
//    framework/shaders/;
//  - a lab: LAB/N/ (a folder laid out like labs/, e.g. a student's copy or a
//    handout), then LAB's folders of the stages N builds on, newest first,
//    then framework/shaders/. The project's labs/N/ is self-contained (it
//    holds the earlier stages' files, solved), so its search ends in labs/N/;
//    a handout's stage folder holds only its own files, and the rest is read
//    from the student's own earlier stage folders beside it, so that a fix in
//    stage 01 shows in 02 and 03.
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
    bool lab = false;  // search starts with a lab's folders (variants go in front of them all)
    std::filesystem::path labRoot;  // a lab's LAB folder; empty for the solution
    // Files no folder of the lab has, taken from the lab as handed out
    // (MissingLabFiles::FromHandedOutLab only).
    std::vector<std::string> filledIn;
};

// What labSources does when a file the stage needs is in none of the lab's
// folders (a student who submitted 03-shadows/ without the 02-shading/ it
// builds on).
enum class MissingLabFiles {
    Error,             // a one-line error naming the files and the folders to copy in
    FromHandedOutLab,  // graders: the lab as handed out at the course's level (lab_folder.h)
};

// SOURCES' search path with the variant folders that DEFINES switch on
// (framework/shaders/variants/<variant>/<stage id>/) in front of the stage
// folders whose files they replace.
std::vector<std::filesystem::path> searchWithVariants(const StageSources& sources,
                                                      const std::vector<std::string>& defines);

StageSources solutionSources(const StageInfo& stage);

// Throws Error when LABROOT or LABROOT/<stage> is missing, or (MissingLabFiles::
// Error) a file the stage needs is in none of the lab's folders.
StageSources labSources(const StageInfo& stage, const std::filesystem::path& labRoot,
                        MissingLabFiles missing = MissingLabFiles::Error);

// labs/ of the project.
std::filesystem::path defaultLabRoot();

}  // namespace raylab
