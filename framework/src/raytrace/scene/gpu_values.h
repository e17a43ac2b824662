#pragma once
// The floats the shaders get for a scene already in the GPU's frame
// (sceneFrame, scene_transform.h): each position and length of the scene,
// held in double, rounded once. The baked program, the uniforms, the sphere
// blocks and the reference tracer (which traces what the GPU is given) all
// take them from here, so they agree to the bit.
#include "scene.h"

#include <glm/glm.hpp>

namespace raylab {

inline glm::vec3 gpuPoint(const glm::dvec3& p) { return glm::vec3(p); }

// Centre at TIME (the bob added in double) and radius.
inline glm::vec4 gpuSphere(const Sphere& s, float time) {
    return {gpuPoint(s.center + s.motion.offsetAt(time)), float(s.radius)};
}
// Unit normal and its offset along it (the plane is dot(n, x) = offset).
inline glm::vec4 gpuPlane(const Plane& p) {
    return {p.normal, float(glm::dot(glm::dvec3(p.normal), p.point))};
}
inline glm::vec4 gpuDisc(const Disc& d) { return {gpuPoint(d.center), float(d.radius)}; }
inline glm::vec4 gpuTorus(const Torus& t) { return {gpuPoint(t.center), float(t.majorRadius)}; }

}  // namespace raylab
