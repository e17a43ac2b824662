#pragma once
// The fur track's GLSL functions in double precision, for the function
// checks: the same conventions as the solution's files (one function each).
#include <glm/glm.hpp>

namespace raylab::fur_reference {

// shell_layer.glsl: the layer the I-th draw call of N draws, 0 (the skin)
// first, 1 (the tips) last.
double shellLayer(int drawIndex, int shellCount);
// shell_offset.glsl: how far a vertex moves: along its (unit) normal by
// layer * furLength.
glm::dvec3 shellOffset(const glm::dvec3& normal, double layer, double furLength);
// shell_alpha.glsl: opaque skin (layer 0); above it the pattern, thinning
// out toward the tips.
double shellAlpha(double pattern, double layer);
// shell_shadow.glsl: 1 - intensity * (1 - layer).
double shellShadow(double layer, double intensity);
// strand_point.glsl: the point at S in [0, 1] along a strand from ROOT that
// grows along NORMAL and bends along GRAVITY (a vector, its length the bend).
glm::dvec3 strandPoint(const glm::dvec3& root, const glm::dvec3& normal, double s, double furLength,
                       const glm::dvec3& gravity);
// kajiya_kay.glsl: (diffuse, specular) of a strand with unit TANGENT lit from
// unit TOLIGHT and seen from unit TOEYE: diffuse = sin(T, L), specular =
// max(0, sin(T, L) sin(T, E) - (T.L)(T.E))^shininess.
glm::dvec2 kajiyaKay(const glm::dvec3& tangent, const glm::dvec3& toLight, const glm::dvec3& toEye,
                     double shininess);

}  // namespace raylab::fur_reference
