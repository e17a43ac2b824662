#pragma once
// How the function checks compare a GLSL result with the double-precision
// reference, shared by the ray tracer's and the fur track's tables.
#include "function_checks.h"

#include <string>

namespace raylab {

std::string caseNumber(double v);  // 6 significant digits, for messages
bool allFinite(const glm::dvec4& v);
// Empty when the first COMPONENTS of GOT are within TOLERANCE of WANT, else
// "LABEL: expected (w0, w1), got (g0, g1)" (or "got NaN or Inf").
std::string compareVector(const FunctionCase& c, const glm::dvec4& got, const glm::dvec4& want,
                          int components, double tolerance);

}  // namespace raylab
