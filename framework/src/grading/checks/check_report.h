#pragma once
// What `raylab check` reports, and how it words it: the verdict of each
// function check, check view and count check, the hints, the summary line.
// One wording for native (cli/cmd_check.cpp) and the page (through the
// WebAssembly core), so a student reads the same report in both.
#include "function_checks.h"
#include "image_compare.h"
#include "shader_source.h"
#include "stage_catalog.h"

#include <string>
#include <vector>

namespace raylab {

// A check view judged: its picture against the reference.
struct ViewOutcome {
    std::string name;
    std::string why;  // what the view checks (stage.json)
    ImageDiff diff;
    long nonFinite = 0;  // NaN or Inf pixels of the student's picture
    bool passed = false;
    std::string hint;  // diagnose()'s, for a failing view; else empty
};

// MINE (the student's picture of VIEW, NONFINITE and TODOPIXELS counted by
// the renderer) against EXPECTED, with the graders' tolerance and hints.
// FUNCTIONFAILED: a function check of the stage failed (its line is the
// evidence; the hint then says the picture's facts only, no usual causes).
ViewOutcome judgeView(const StageInfo& stage, const CheckView& view, const Image& mine,
                      const Image& expected, long nonFinite, long todoPixels,
                      bool functionFailed = false);

// The causes REPORT (a `raylab check` report of STAGE, or a grading
// result's check outputs) names, as the mistakes catalogue's "hints" name
// them: "darker" and "brighter" (stage.json's usual causes), "view:NAME" (a
// check view's own "hint"), "FUNCTION:ID" (a function check's diagnosis).
// Sorted, each once.
std::vector<std::string> causesNamed(const std::string& report, const StageInfo& stage);

// A count check over the check views: a number the GPU produced against the
// same number worked out on the CPU (the fur track's fin_count).
struct CountOutcome {
    std::string name;
    int passed = 0, total = 0;
    std::string firstFailure;  // "view side: the geometry shader emitted ..."
    std::string example;       // the first view's detail, for a passing report
};

// "raylab: 2 open TODOs in this lab (...):" and one line per TODO; empty
// for none.
std::string formatOpenTodos(const std::vector<OpenTodo>& todos);

// The report's lines, each ending in a newline, as `raylab check` prints
// them in this order.
std::string formatFunctionsHeading();  // before the first function check
// A function's hint (its diagnosis) is printed only when no function check
// before it failed: later checks call the earlier functions (04's trace calls
// refractGlass), so their pattern may be the earlier function's slip.
// EARLIERFAILED: a function check printed before this one failed.
std::string formatFunctionLine(const FunctionOutcome& f, bool earlierFailed = false);
// Under a failing function check whose harness reads the file of a function
// that failed above (findClosest's reads intersect_sphere.glsl): a note that
// says so, since that slip can be all this check sees ("one sphere ahead"
// failing when only intersectSphere returns the far root). Empty otherwise,
// and for a file that is the check's own (fresnelConductor shares
// fresnel.glsl with fresnelDielectric without calling it). SPEC: the failing
// check's, with its harness GLSL; FAILEDABOVE: the failed checks' specs.
std::string formatReadsFailedNote(const FunctionSpec& spec,
                                  const std::vector<const FunctionSpec*>& failedAbove);
std::string formatViewsHeading();  // the tolerance, before the first view
// FAILEDFUNCTIONS: the function checks that failed above (a note points at
// the first when the view has no hint); OPENTODOS: the lab's open TODOs.
std::string formatViewLines(const ViewOutcome& v, const std::vector<std::string>& failedFunctions,
                            std::size_t openTodos);
std::string formatCountLine(const CountOutcome& c);
std::string formatSummary(int passed, int failed);  // "3 passed, 1 failed"

bool countPassed(const CountOutcome& c);

// Adds one view's result of a count check to C (its example and first failure).
void tallyCount(CountOutcome& c, const std::string& view, bool passed, const std::string& detail);

}  // namespace raylab
