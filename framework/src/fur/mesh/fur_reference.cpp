#include "fur_reference.h"

#include <algorithm>
#include <cmath>

namespace raylab::fur_reference {

double shellLayer(int drawIndex, int shellCount) {
    return shellCount > 1 ? double(drawIndex) / double(shellCount - 1) : 0.0;
}

glm::dvec3 shellOffset(const glm::dvec3& normal, double layer, double furLength) {
    return layer * furLength * glm::normalize(normal);
}

double shellAlpha(double pattern, double layer) {
    return layer <= 0.0 ? 1.0 : pattern * (1.0 - layer);
}

double shellShadow(double layer, double intensity) { return 1.0 - intensity * (1.0 - layer); }

glm::dvec3 strandPoint(const glm::dvec3& root, const glm::dvec3& normal, double s, double furLength,
                       const glm::dvec3& gravity) {
    return root + furLength * (s * glm::normalize(normal) + s * s * gravity);
}

glm::dvec2 kajiyaKay(const glm::dvec3& tangent, const glm::dvec3& toLight, const glm::dvec3& toEye,
                     double shininess) {
    const double tl = glm::dot(tangent, toLight), te = glm::dot(tangent, toEye);
    const double sinTl = std::sqrt(std::max(0.0, 1.0 - tl * tl));
    const double sinTe = std::sqrt(std::max(0.0, 1.0 - te * te));
    return {sinTl, std::pow(std::max(0.0, sinTl * sinTe - tl * te), shininess)};
}

}  // namespace raylab::fur_reference
