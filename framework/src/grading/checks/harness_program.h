#pragma once
// The program a function check runs: a one-row float target, one pixel per
// case; the harness fragment shader reads the case's inputs from a float
// texture (uCases, 4 rows: row k holds input a<k> of every case), calls the
// student's function and writes its result. Assembled here, on the CPU, for
// native (grading/function_harness.cpp) and for the page (WebGL 2), so both
// compile the same text from the same files.
#include "function_checks.h"
#include "shader_source.h"
#include "stage_sources.h"

#include <string>
#include <vector>

namespace raylab {

// The harness's entry file, generated for SPEC (the text of harness.frag).
std::string harnessSource(const FunctionSpec& spec);

struct HarnessProgram {
    ShaderSource vertex;    // the framework's full-screen canvas.vert
    ShaderSource fragment;  // harness.frag: the stage's files through its search path
};

// Assembles SPEC's harness through the stage's search path in SOURCES (the
// stage's defines plus EXTRADEFINES, e.g. "TORUS_SOLVER_CLOSED_FORM" for
// the numerics tests). WEBGL2: GLSL ES 3.00 with web/shaders first, as the
// page's stage programs. Throws Error for a missing or forbidden #include.
HarnessProgram assembleHarness(const FunctionSpec& spec, const StageInfo& stage,
                               const StageSources& sources,
                               const std::vector<std::string>& extraDefines = {},
                               bool webGl2 = false);

// uCases' texels: RGBA floats, N wide (one per case) and 4 rows.
std::vector<float> harnessCaseTexels(const FunctionSpec& spec);

// True when some case sets uniforms of its own (FunctionCase::uniforms):
// the harness is then drawn one pixel at a time.
bool harnessDrawsPerCase(const FunctionSpec& spec);

}  // namespace raylab
