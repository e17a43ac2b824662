#pragma once
// The scene file's triangles in groups: runs of consecutive triangles of one
// material (the faces of one box, the two halves of one rectangle), each
// with the box around its corners. Stage 08 tests a group's triangles only
// when the ray meets its box (solution/08-full/find_closest.glsl), in a
// plain loop: a ray that misses the glass cube skips its 12 triangles.
//
// Why not the BVH: stage 08's scenes have at most 32 of these triangles, and
// through the tree pro takes 15% longer (bvh.h, the bench's tree-all row).
// A loop over a few groups runs in step on llvmpipe's 8 lock-step pixels
// and, in the specialised program, over constant boxes. (llvmpipe still runs
// one pass of a skipped group's loop with every pixel masked off: a missed
// box costs one triangle test, not its dozen.)
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct TriangleGroup {
    int first = 0;  // index of its first triangle in scene.triangles
    int count = 0;  // consecutive triangles, at most kTriangleGroupMax
    // The corners' smallest and largest coordinates (exact, not padded). In
    // double, like the corners; rounded to the nearest float they are the box
    // of the float corners the GPU gets (rounding keeps the order).
    glm::dvec3 lo{0.0}, hi{0.0};
};

// A group holds at most this many triangles: a long run of one material
// (a model written out as triangles) gets several boxes, tighter ones.
inline constexpr int kTriangleGroupMax = 12;

std::vector<TriangleGroup> triangleGroups(const Scene& scene);

}  // namespace raylab
