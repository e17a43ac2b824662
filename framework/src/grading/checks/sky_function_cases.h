#pragma once
// The function checks of what a ray sees beyond the scene's objects (stage
// 06): the sky (skyColor) and the glow around the sun (sunGlow), in
// sky_function_cases.cpp.
#include "function_checks.h"

namespace raylab {

FunctionSpec skyColorSpec();
FunctionSpec sunGlowSpec();

}  // namespace raylab
