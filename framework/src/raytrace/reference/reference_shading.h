#pragma once
// The double-precision references of the shading and texturing functions
// that students write: used by the reference tracer and by the function
// checks alike, so there is one reference per GLSL function (see
// reference_intersect.h for the intersections).
#include <glm/glm.hpp>

namespace raylab::reference {

// fresnel.glsl: Schlick's reflectance of glass of index IOR, with the cosine
// on the air side.
double fresnelDielectric(double cosOutside, double ior);

// fresnel.glsl: Schlick per colour channel for a metal of complex index n + ik.
glm::dvec3 fresnelConductor(double cosIncident, const glm::dvec3& n, const glm::dvec3& k);

// sphere_uv.glsl: longitude and latitude of the unit direction D, in [0, 1].
glm::dvec2 sphereUV(const glm::dvec3& d);

// plane_uv.glsl: POINT's coordinates on the plane through ORIGIN with unit
// normal N, in tiles of size TILE.
glm::dvec2 planeUV(const glm::dvec3& point, const glm::dvec3& origin, const glm::dvec3& n,
                   double tile);

}  // namespace raylab::reference
