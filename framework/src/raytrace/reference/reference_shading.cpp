#include "reference_shading.h"

#include <algorithm>
#include <cmath>

namespace raylab::reference {

namespace {
constexpr double kPi = 3.14159265358979323846;

double schlick(double f0, double cosine) {
    return f0 + (1.0 - f0) * std::pow(std::clamp(1.0 - cosine, 0.0, 1.0), 5.0);
}
}  // namespace

double fresnelDielectric(double cosOutside, double ior) {
    double f0 = (ior - 1.0) / (ior + 1.0);
    return schlick(f0 * f0, cosOutside);
}

glm::dvec3 fresnelConductor(double cosIncident, const glm::dvec3& n, const glm::dvec3& k) {
    const glm::dvec3 f0 = ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
    return {schlick(f0.x, cosIncident), schlick(f0.y, cosIncident), schlick(f0.z, cosIncident)};
}

glm::dvec2 sphereUV(const glm::dvec3& d) {
    const double phi = std::atan2(-d.z, d.x);
    const double theta = std::asin(std::clamp(d.y, -1.0, 1.0));
    return {0.5 + phi / (2.0 * kPi), 0.5 + theta / kPi};
}

glm::dvec2 planeUV(const glm::dvec3& point, const glm::dvec3& origin, const glm::dvec3& n,
                   double tile) {
    const glm::dvec3 helper =
        std::fabs(n.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 axisU = glm::normalize(glm::cross(n, helper));
    const glm::dvec3 axisV = glm::cross(n, axisU);
    const glm::dvec3 offset = point - origin;
    return glm::dvec2(glm::dot(offset, axisU), glm::dot(offset, axisV)) / tile;
}

}  // namespace raylab::reference
