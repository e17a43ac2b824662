#pragma once
// The fur track's function-check tables (fur_function_cases.cpp).
#include "function_checks.h"

#include <vector>

namespace raylab {

std::vector<FunctionSpec> furFunctionSpecs();

}  // namespace raylab
