#pragma once
// Ray/object intersections of the reference tracer, in double precision:
// the same objects and the same rules as the GLSL of solution/ (hits at
// t <= T_MIN do not count, both sides of a triangle count, the tests for
// parallel rays), but solved as exactly as double allows, so that the
// reference is the ground truth where float rounding is the question.
#include "shader_constants.h"

#include <glm/glm.hpp>

namespace raylab::reference {

// T_MIN and NO_HIT of the GLSL.
using shader::kNoHit;
using shader::kTMin;

struct DRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 dir{0.0, 0.0, -1.0};  // unit
};

// The nearest t > kTMin, or kNoHit. (intersect_sphere.glsl; the quadratic
// solved without cancellation: h from the distance of the centre to the
// line, the far root from the product of the roots.)
double intersectSphere(const DRay& ray, const glm::dvec3& center, double radius);

// The plane dot(normal, p) = offset (intersect_plane.glsl): kNoHit for
// |dot(normal, dir)| < 1e-6 (as the GLSL: a ray along the plane) or t <= kTMin.
double intersectPlane(const DRay& ray, const glm::dvec3& normal, double offset);

// The plane through CENTER with NORMAL, within RADIUS of the centre (intersect_disc.glsl).
double intersectDisc(const DRay& ray, const glm::dvec3& center, const glm::dvec3& normal,
                     double radius);

// Moller-Trumbore with the GLSL's rejections (|det| < 1e-10, u or v outside
// the triangle, t <= kTMin) (intersect_triangle.glsl).
double intersectTriangle(const DRay& ray, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c);

// A torus in its own frame (centre at the origin, axis +z), ring radius R,
// tube radius r < R: the nearest t > kTMin or kNoHit. The quartic along the
// ray is solved inside the bounding sphere by isolating its real roots
// between the roots of its derivatives (monotone pieces, each bisected to
// double precision on the sign of the exact distance function), so no root
// is lost or invented except at an exact tangency.
double intersectTorusLocal(const DRay& ray, double R, double r);

// Unit outward normal of the torus at a point of its surface (torus frame):
// the normalised gradient (|p|^2 + R^2 - r^2) p - 2 R^2 (p.x, p.y, 0).
glm::dvec3 torusNormalLocal(const glm::dvec3& p, double R, double r);

// Distance from P to the torus surface, negative inside the tube.
double torusDistance(const glm::dvec3& p, double R, double r);

// World-to-local rotation of a torus whose (unit) axis is AXIS: the rows are
// x, y, axis, built as scene.h's torusToLocal (the GPU's) does.
glm::dmat3 torusToLocal(const glm::dvec3& axis);

}  // namespace raylab::reference
