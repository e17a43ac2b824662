#pragma once
// A stage of a lab reads the student's own folders of the stages it builds on
// (stage_sources.h, EarlierStages::Own): a slip in 01's findClosest breaks
// 02's and 03's pictures too, and their own checks would send the student to
// the wrong files. Before a stage's own checks, `raylab check` (and the
// page) run the function checks of those earlier stages on the files this
// stage reads from them, and a failure is reported first, naming the earlier
// stage's file. Grading (earlier stages solved by default) names them too.
// No GL here: the checks run through function_harness.h (native) or the page.
#include "function_checks.h"
#include "stage_catalog.h"
#include "stage_sources.h"

#include <string>
#include <vector>

namespace raylab {

// A function check of an earlier stage whose function lives in a file the
// lab reads from the student's own folder of that stage.
struct EarlierFunctionCheck {
    const StageInfo* stage = nullptr;  // the earlier stage that checks it
    const FunctionSpec* spec = nullptr;
    std::string file;   // the student's file that defines it, as displayed
    std::string inLab;  // the same, relative to the lab folder ("01-raycast/find_closest.glsl")
};

// For the lab in SOURCES (a lab's sources, earlier stages its own), newest
// earlier stage first. Empty when the lab reads no earlier stage's folder.
std::vector<EarlierFunctionCheck> earlierFunctionChecks(const StageInfo& stage,
                                                        const StageSources& sources);

// The file among FILES (paths) that defines the GLSL function NAME (a line
// "TYPE NAME(" outside comments); empty when none does.
std::string fileDefining(const std::string& name, const std::vector<std::filesystem::path>& files);

struct EarlierFailure {
    EarlierFunctionCheck check;
    FunctionOutcome outcome;
};

// What `raylab check` prints first when an earlier stage's file fails
// (empty for none): the file, the function, its first failing case, and
// that this stage's checks below go wrong with it. LABARG: the " --lab DIR"
// of the command to check that stage ("" for the project's labs/).
std::string formatEarlierFailures(const StageInfo& stage,
                                  const std::vector<EarlierFailure>& failures,
                                  const std::string& labArg);

// One line for a grading result: the stage was graded with the earlier
// stages solved, and the student's own earlier file that fails.
std::string earlierFailuresNote(const std::vector<EarlierFailure>& failures);

}  // namespace raylab
