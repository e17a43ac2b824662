#pragma once
// The silhouette test of the fin shader, in double precision: the reference
// for the function check of isSilhouette() and for the fin count check (the
// number of fins the geometry shader emits for a mesh and a camera). It is
// TODO f3.a's answer: the page's core and a student repository are built
// without it and read what it gives as data (function_tables.h,
// count_tables.h).
#include "adjacency.h"
#include "fin_count.h"

#include <glm/glm.hpp>

namespace raylab {

// dot(PB, N_abc) * dot(PB, N_bcd) with N_abc = cross(B - A, C - B) and
// N_bcd = cross(D - B, C - B), PB = B - P (the seed's formulas). Negative:
// one triangle faces the eye P and the other faces away.
double silhouetteProduct(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c, const glm::dvec3& d);

// Is the product so close to zero that float rounding may decide its sign?
// True when a factor is within what float can move it: 1e-4 of its size
// (|PB| |N|), plus the rounding of world positions far from the origin
// (silhouette.cpp); a float test of either answer is then right. A factor
// that is exactly zero (a degenerate triangle, the eye on B) is zero in
// float too, and the product is then certainly no silhouette.
bool silhouetteUncertain(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c, const glm::dvec3& d);

// Silhouette edges of ADJACENCY's edges of MESH placed by MODEL, seen from EYE
// (world space): a correct fin shader emits between `certain` and
// `certain + uncertain` fins.
SilhouetteCount countSilhouettes(const Mesh& mesh, const EdgeAdjacency& adjacency,
                                 const glm::dmat4& model, const glm::dvec3& eye);

}  // namespace raylab
