#pragma once
// The function check of stage 08's walkBvh: the student's walk through a
// bounding volume hierarchy of spheres (bvh_function_cases.cpp).
#include "function_checks.h"

namespace raylab {

FunctionSpec walkBvhSpec();

}  // namespace raylab
