#include "function_compare.h"

#include "text_format.h"

#include <cmath>
#include <cstdio>

namespace raylab {

std::string caseNumber(double v) { return significant(v, 6); }

std::string caseVector(const glm::dvec3& v) {
    return "(" + caseNumber(v.x) + ", " + caseNumber(v.y) + ", " + caseNumber(v.z) + ")";
}

glm::dvec4 asHarnessReads(const glm::dvec4& v) {
    glm::dvec4 out;
    for (int i = 0; i < 4; ++i) out[i] = double(static_cast<float>(v[i]));
    return out;
}

std::string glslFloat(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", v);
    std::string s = b;
    if (s.find_first_of(".en") == std::string::npos) s += ".0";
    return s;
}

bool allFinite(const glm::dvec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

FunctionCase caseOf(std::string label, glm::dvec4 a0, glm::dvec4 a1, glm::dvec4 a2, glm::dvec4 a3) {
    FunctionCase c;
    c.label = std::move(label);
    c.in = {a0, a1, a2, a3};
    return c;
}

std::string compareVector(const FunctionCase& c, const glm::dvec4& got, const glm::dvec4& want,
                          int components, double tolerance) {
    if (!allFinite(got)) return c.label + ": got NaN or Inf";
    for (int i = 0; i < components; ++i)
        if (std::fabs(got[i] - want[i]) > tolerance) {
            std::string g, w;
            for (int j = 0; j < components; ++j) {
                g += (j ? ", " : "") + caseNumber(got[j]);
                w += (j ? ", " : "") + caseNumber(want[j]);
            }
            return c.label + ": expected (" + w + "), got (" + g + ")";
        }
    return "";
}

}  // namespace raylab
