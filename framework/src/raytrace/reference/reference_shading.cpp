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

LightTerms blinnPhongLight(const glm::dvec3& normal, const glm::dvec3& toEye,
                           const glm::dvec3& toLight, const glm::dvec3& lightColor,
                           const glm::dvec3& diffuse, const glm::dvec3& specular,
                           double shininess) {
    LightTerms out;
    out.lambert = std::max(glm::dot(normal, toLight), 0.0);
    out.diffuse = lightColor * diffuse * out.lambert;
    if (out.lambert > 0.0) {
        const glm::dvec3 halfway = glm::normalize(toLight + toEye);
        out.specular =
            lightColor * specular * std::pow(std::max(glm::dot(normal, halfway), 0.0), shininess);
    }
    return out;
}

glm::dvec3 refract(const glm::dvec3& I, const glm::dvec3& N, double eta) {
    const double cosI = glm::dot(N, I);
    const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (k < 0.0) return glm::dvec3(0.0);
    return eta * I - (eta * cosI + std::sqrt(k)) * N;
}

glm::dvec4 refractGlass(const glm::dvec3& dir, const glm::dvec3& normal, bool entering,
                        double ior) {
    const double eta = entering ? 1.0 / ior : ior;
    const glm::dvec3 refracted = refract(dir, normal, eta);
    if (refracted == glm::dvec3(0.0)) return {0.0, 0.0, 0.0, 1.0};  // total internal reflection
    const double cosIncident = -glm::dot(dir, normal),
                 cosTransmitted = -glm::dot(refracted, normal);
    return {refracted, fresnelDielectric(entering ? cosIncident : cosTransmitted, ior)};
}

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

glm::dvec3 applyNormalMap(const glm::dvec3& N, const glm::dvec3& tangent, const glm::dvec3& m) {
    const glm::dvec3 along = tangent - glm::dot(tangent, N) * N;
    if (glm::length(along) == 0.0) return N;  // no tangent (the GLSL would give NaN)
    const glm::dvec3 T = glm::normalize(along);
    const glm::dvec3 B = glm::cross(N, T);
    return glm::normalize(T * m.x + B * m.y + N * m.z);
}

glm::dvec3 applyColorMode(const glm::dvec3& c, int mode) {
    switch (mode) {
    case 1: return {c.b, c.r, c.b};
    case 2: return {c.b, c.r, c.r};
    case 3: return {c.r, c.b, c.b};
    case 4: return {c.g, c.g, c.r};
    default: return c;
    }
}

}  // namespace raylab::reference
