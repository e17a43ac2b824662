#pragma once
// The double-precision references of the shading and texturing functions
// that students write: used by the reference tracer and by the function
// checks alike, so there is one reference per GLSL function (see
// reference_intersect.h for the intersections).
#include <glm/glm.hpp>

namespace raylab::reference {

// blinn_phong.glsl, one light: the diffuse and specular terms of a light of
// colour LIGHTCOLOR in the unit direction TOLIGHT, at a point with unit
// normal NORMAL seen from the unit direction TOEYE. No specular where the
// light is behind the surface (N . L <= 0).
struct LightTerms {
    double lambert = 0.0;  // max(N . L, 0)
    glm::dvec3 diffuse{0.0}, specular{0.0};
};
LightTerms blinnPhongLight(const glm::dvec3& normal, const glm::dvec3& toEye,
                           const glm::dvec3& toLight, const glm::dvec3& lightColor,
                           const glm::dvec3& diffuse, const glm::dvec3& specular, double shininess);

// GLSL refract(): vec3(0) under total internal reflection.
glm::dvec3 refract(const glm::dvec3& I, const glm::dvec3& N, double eta);

// trace.glsl's glass (refractGlass): the refracted direction of the unit
// ray direction DIR at a surface of index IOR whose unit NORMAL faces the
// ray, ENTERING from the air or leaving the glass, in xyz, and the share F
// of the light that is reflected in w: (0, 0, 0, 1) under total internal
// reflection.
glm::dvec4 refractGlass(const glm::dvec3& dir, const glm::dvec3& normal, bool entering, double ior);

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

// normal_map.glsl: the unit normal N tilted by the decoded normal-map texel
// M (tangent space, -1..1) in the frame of TANGENT made perpendicular to N
// and unit (Gram-Schmidt). N itself where TANGENT is along N.
glm::dvec3 applyNormalMap(const glm::dvec3& N, const glm::dvec3& tangent, const glm::dvec3& m);

// color_mode.glsl: the channels of C in the order of colour mode MODE
// (0 RGB, 1 BRB, 2 BRR, 3 RBB, 4 GGR).
glm::dvec3 applyColorMode(const glm::dvec3& c, int mode);

}  // namespace raylab::reference
