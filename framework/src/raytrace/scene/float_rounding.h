#pragma once
// From the scene's doubles to the floats the GPU reads. A position or length
// is rounded to the nearest float (glm::vec3(p)); a bound that must still
// hold everything it held in double - a box's corners, a cell's reach - is
// rounded outward instead: a minimum down, a maximum up.
#include <glm/glm.hpp>

#include <cmath>
#include <limits>

namespace raylab {

// The largest float at or below X, and the smallest at or above it.
inline float floatBelow(double x) {
    const float f = float(x);
    return double(f) <= x ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
inline float floatAbove(double x) {
    const float f = float(x);
    return double(f) >= x ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}
inline glm::vec3 floatBelow(const glm::dvec3& p) {
    return {floatBelow(p.x), floatBelow(p.y), floatBelow(p.z)};
}
inline glm::vec3 floatAbove(const glm::dvec3& p) {
    return {floatAbove(p.x), floatAbove(p.y), floatAbove(p.z)};
}

}  // namespace raylab
