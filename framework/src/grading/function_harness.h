#pragma once
// Function checks run natively: the harness program (checks/harness_program.h)
// drawn into a one-row float target on the current GL context, and scored
// (checks/function_checks.h). Used by `raylab check` and `raylab grade`.
#include "earlier_stage_checks.h"
#include "function_checks.h"
#include "stage_sources.h"

#include <string>
#include <vector>

namespace raylab {

// Runs SPEC's table through the stage's shader files in SOURCES. Needs a
// current GL context. A harness that does not compile is an outcome
// (compiled = false), not an exception.
FunctionOutcome runFunctionCheck(const FunctionSpec& spec, const StageInfo& stage,
                                 const StageSources& sources);

// The function checks of the earlier stages that the lab in SOURCES reads
// from the student's own folders (earlier_stage_checks.h), run on those
// folders; the failing ones, newest earlier stage first. Needs a current GL
// context.
std::vector<EarlierFailure> runEarlierFunctionChecks(const StageInfo& stage,
                                                     const StageSources& sources);

// The raw harness output: one vec4 per case (w = kHarnessTodoMarker when the
// call reached a labTodo() stub). EXTRADEFINES are added to the stage's
// (e.g. "TORUS_SOLVER_CLOSED_FORM" for the numerics tests). Throws Error or
// ShaderError when the harness does not compile.
std::vector<glm::vec4> runHarness(const FunctionSpec& spec, const StageInfo& stage,
                                  const StageSources& sources,
                                  const std::vector<std::string>& extraDefines = {});

}  // namespace raylab
