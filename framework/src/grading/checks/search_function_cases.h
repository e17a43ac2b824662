#pragma once
// The function check of stage 05's findClosest, the search over every kind
// of object (search_function_cases.cpp).
#include "function_checks.h"

namespace raylab {

FunctionSpec findClosestEveryKindSpec();

}  // namespace raylab
