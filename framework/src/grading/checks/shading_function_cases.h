#pragma once
// The function-check tables of the ray tracer's functions that need a scene
// (lights, spheres, a normal-map texel, a key's uniform):
// shading_function_cases.cpp.
#include "function_checks.h"

#include <vector>

namespace raylab {

std::vector<FunctionSpec> shadingFunctionSpecs();

}  // namespace raylab
