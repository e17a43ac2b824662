#pragma once
// How the function checks compare a GLSL result with the double-precision
// reference, shared by the ray tracer's and the fur track's tables.
#include "function_checks.h"

#include <string>

namespace raylab {

std::string caseNumber(double v);             // 6 significant digits, for messages
std::string caseVector(const glm::dvec3& v);  // "(x, y, z)", each as caseNumber
// A GLSL float literal of V (9 significant digits: a float exactly), for
// tables a harness is given as code (the worlds of trace and walkBvh).
std::string glslFloat(double v);
// V as the harness reads it: each component rounded to float. (Written per
// component: g++ -O3 left two of three components of a glm::vec3(dvec3)
// conversion unrounded in one function here, while -O0 rounded them.)
glm::dvec4 asHarnessReads(const glm::dvec4& v);

// A case of a table: its label and its inputs a0..a3.
FunctionCase caseOf(std::string label, glm::dvec4 a0, glm::dvec4 a1 = glm::dvec4(0.0),
                    glm::dvec4 a2 = glm::dvec4(0.0), glm::dvec4 a3 = glm::dvec4(0.0));
bool allFinite(const glm::dvec4& v);
// A case input's first three components (a point or a direction).
inline glm::dvec3 xyz(const glm::dvec4& v) { return glm::dvec3(v); }
// Empty when the first COMPONENTS of GOT are within TOLERANCE of WANT, else
// "LABEL: expected (w0, w1), got (g0, g1)" (or "got NaN or Inf").
std::string compareVector(const FunctionCase& c, const glm::dvec4& got, const glm::dvec4& want,
                          int components, double tolerance);

}  // namespace raylab
