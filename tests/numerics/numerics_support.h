#pragma once
// Shared by the numerics tests: a headless GL context for the whole test
// program, and error statistics in float ulps.
#include "function_harness.h"
#include "stage_sources.h"
#include "test_support.h"

#include <memory>
#include <vector>

namespace raylab::numerics {

// A headless GL context, made on first use and kept for the whole run.
using raylab::test::ensureGlContext;

// Spacing of float32 numbers at |x|: the smallest error float can show there.
double floatUlp(double x);

// The p-th percentile (0..100) of VALUES (sorted copy); 0 for none.
double percentile(std::vector<double> values, double p);

// Runs SPEC's cases through stage ID's solution with EXTRADEFINES. The
// harness finds tests/numerics/glsl/ (the tests' GLSL helpers) first, and
// any number of cases is run in pieces.
std::vector<glm::vec4> runSolution(const FunctionSpec& spec, const std::string& stageId,
                                   const std::vector<std::string>& extraDefines = {});

inline float f32(double x) { return float(x); }

}  // namespace raylab::numerics
