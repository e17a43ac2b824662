#pragma once
// The function check of stage 04's trace(): the student's tracer, loop and
// stack, run in small worlds of spheres against a recursive tracer in double
// precision (trace_function_cases.cpp).
#include "function_checks.h"

namespace raylab {

FunctionSpec traceSpec();

}  // namespace raylab
