#pragma once
// Lab f1's function-check tables (mesh_function_cases.cpp).
#include "function_checks.h"

#include <vector>

namespace raylab {

std::vector<FunctionSpec> meshFunctionSpecs();

}  // namespace raylab
