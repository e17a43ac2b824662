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
    // EarlierStages::Solved: the earlier stages' files come from solution/.
    bool earlierSolved = false;
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

// Where a lab's files of the earlier stages it builds on come from.
//  - Own: the student's own folders of those stages beside it (LAB/01-raycast/
//    for 02-shading), what `raylab run` and `check` draw: a fix in stage 01
//    shows in 02 at once, and so does a slip.
//  - Solved: the course's solutions of those stages (solution/<earlier>/),
//    what grading uses by default: a slip in 01 costs in 01 only, and each
//    stage is graded on its own work (course_file.h, "earlier_stages").
enum class EarlierStages { Own, Solved };

// "own" or "solved"; throws Error("WHERE: ...") otherwise.
EarlierStages parseEarlierStages(const std::string& value, const std::string& where);

// Throws Error when LABROOT or LABROOT/<stage> is missing, or (MissingLabFiles::
// Error) a file the stage needs is in none of the lab's folders.
StageSources labSources(const StageInfo& stage, const std::filesystem::path& labRoot,
                        MissingLabFiles missing = MissingLabFiles::Error,
                        EarlierStages earlier = EarlierStages::Own);

// The earlier stages whose files a lab's programs read from the student's
// own folders (LAB/<earlier>/, not the stage's own folder nor the
// framework), newest first, each with the file names read there. Empty for
// a self-contained lab folder (labs/<stage>/ holds every earlier file).
struct OwnEarlierStage {
    std::string id;                  // "01-raycast"
    std::vector<std::string> files;  // "find_closest.glsl", ...
};
std::vector<OwnEarlierStage> ownEarlierStagesRead(const StageInfo& stage,
                                                  const StageSources& sources);

// labs/ of the project.
std::filesystem::path defaultLabRoot();

}  // namespace raylab
