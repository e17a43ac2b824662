#pragma once
// The silhouette test of the fin shader, in double precision: the reference
// for the function check of isSilhouette() and for the fin count check (the
// number of fins the geometry shader emits for a mesh and a camera).
#include "adjacency.h"

#include <glm/glm.hpp>

#include <string>

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

struct SilhouetteCount {
    long certain = 0;    // edges that are silhouettes beyond doubt
    long uncertain = 0;  // edges too close to edge-on to call
};

// Silhouette edges of ADJACENCY's edges of MESH placed by MODEL, seen from EYE
// (world space): a correct fin shader emits between `certain` and
// `certain + uncertain` fins.
SilhouetteCount countSilhouettes(const Mesh& mesh, const EdgeAdjacency& adjacency,
                                 const glm::dmat4& model, const glm::dvec3& eye);

// The fin count check's verdict on EMITTED fins (native: a query of the
// real geometry shader; the page: its emulation's transform feedback)
// against CPU, for a mesh of EDGES edges, in the report's words.
struct FinCountVerdict {
    bool passed = false;
    std::string detail;  // "the geometry shader emitted 12 fins for 96 edges; ..."
};
FinCountVerdict judgeFinCount(long emitted, std::size_t edges, const SilhouetteCount& cpu);

}  // namespace raylab
