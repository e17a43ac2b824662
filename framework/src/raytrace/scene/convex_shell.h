#pragma once
// Closed convex shells among a scene file's triangles: pro's glass cube is
// one. Two levers build on them: a torus inside one is hidden from every
// light outside it (hidden_tori.h), and a ray meets only some of a shell's
// faces first (shell_slots.h). (Students need not read this file.)
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct ConvexShell {
    std::vector<int> triangles;       // indices into scene.triangles, ascending
    std::vector<glm::dvec3> normals;  // per triangle: its face's outward unit normal
    std::vector<glm::dvec3> points;   // per triangle: a point on its face (its first corner)
    double size = 0.0;                // the diagonal of its corners' box
    // How far from its face plane a corner may lie and still count as on
    // it: a box's face is two triangles, whose corners sit off one another's
    // plane by the rounding of the file's numbers.
    double flat = 0.0;
};

// The scene's triangles that share corners (exactly equal coordinates) and
// form a closed convex shell: every edge shared by exactly two of them,
// every corner on or inside every face plane, no triangle degenerate.
std::vector<ConvexShell> convexShells(const Scene& scene);

// Signed distance from P to the plane of the shell's I-th triangle's face
// (positive outside).
double planeDistance(const ConvexShell& shell, std::size_t i, glm::dvec3 p);

}  // namespace raylab
