#pragma once
// The function checks of lightVisible, lab 03's and the full demo's (08):
// visibility_function_cases.cpp.
#include "function_checks.h"

namespace raylab {

FunctionSpec lightVisibilitySpec();
FunctionSpec lightVisibleFastSpec();

}  // namespace raylab
