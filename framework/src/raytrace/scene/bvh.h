#pragma once
// A bounding volume hierarchy over a scene's spheres and mesh triangles
// (and, as a bench row, its own triangles and discs too), built on the CPU
// once per scene and traversed in GLSL by solution/08-full/test_spheres.glsl.
//
// Why: with a linear search every ray tests every object - 110 spheres, 3
// shadow rays per hit and up to 8 bounces make the pro scene slow. A BVH lets
// a ray skip whole groups of spheres whose box it misses.
//
// Why not the scene file's triangles and discs (stage 08 allows 32 and 4):
// so few are tested faster in a loop than through the tree. Measured on pro
// (14 triangles, a disc): with them in the tree a frame takes 15% longer,
// on lite 16% (`raylab bench`, row tree-all; docs/bench/README.md).
// llvmpipe runs every loop body at least once, so each walk step would
// also run a triangle test and a disc test; the loop over the scene's few
// triangles runs in step for all 8 lock-step pixels and, in the
// specialised program, over constant corners (triangle_groups.h).
//
// Why one kind per leaf: llvmpipe runs 8 pixels in lock-step and executes
// both sides of a divergent `if`; a leaf of mixed kinds needs an `if` on the
// kind at every object, so every sphere test would also run the other kind's
// code (measured on a discarded first version with the torus in the tree,
// pro at 400x300: 2157 ms a frame against 453 ms with it taken out). So a
// node whose items are of both kinds is split by kind first, and the `if`
// is paid once per leaf. Planes (unbounded) and the torus (long code) stay
// in plain loops, and so, by default, do the scene's triangles and discs.
//
// Moving spheres: a sphere's box covers its whole bob (centre +- amplitude
// along the motion axis), so one hierarchy is valid at every time and never
// has to be rebuilt or refitted.
#include "scene.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace raylab {

// In double, like the scene (scene.h); packedBvhNodes rounds each box
// outward to the floats the GPU reads.
struct Aabb {
    glm::dvec3 lo{1e300};
    glm::dvec3 hi{-1e300};
    void grow(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    void grow(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    glm::dvec3 centre() const { return 0.5 * (lo + hi); }
    double area() const;  // surface area (0 for an empty box)
    bool contains(const Aabb& b) const;
};

// A node is a leaf when count > 0: it holds items[first .. first + count).
// An inner node has count == 0 and its two children at nodes[first] and
// nodes[first + 1] (siblings are stored next to each other).
// A leaf's items are all of one kind: KIND_SPHERE, KIND_MESH, KIND_TRIANGLE
// or KIND_DISC (shader_constants.h); its items are indices into that kind's
// list.
struct BvhNode {
    Aabb box;
    int first = 0;
    int count = 0;
    int kind = 0;  // leaves only
};

struct Bvh {
    std::vector<BvhNode> nodes;  // nodes[0] is the root (absent when there are no items)
    std::vector<int> items;      // indices into the lists of the leaves' kinds
    int depth = 0;               // longest root-to-leaf path, in nodes
};

// The box of sphere INDEX over all times (see above), a little padded.
Aabb sphereBounds(const Scene& scene, int index);

// The box of mesh triangle INDEX (all meshes' triangles in one list), a little padded.
Aabb meshTriangleBounds(const Scene& scene, int index);

// The box of the scene file's triangle INDEX, and of disc INDEX, a little padded.
Aabb triangleBounds(const Scene& scene, int index);
Aabb discBounds(const Scene& scene, int index);

// The corners of mesh triangle INDEX, counter-clockwise from the front.
std::array<glm::dvec3, 3> meshTriangleCorners(const Scene& scene, int index);

// What goes into the tree: spheres and mesh triangles, or (RAYLAB_TREE_ALL,
// the bench's tree-all row) also the scene file's triangles and discs.
enum class BvhObjects { SpheresAndMeshes, AllBounded };

// Builds the hierarchy of SCENE's OBJECTS with the surface area heuristic
// (binned), at most MAXLEAF items per leaf, one kind per leaf.
// Deterministic for a given scene.
Bvh buildBvh(const Scene& scene, int maxLeaf = 2,
             BvhObjects objects = BvhObjects::SpheresAndMeshes);

// A leaf's code is kBvhLeafKinds * count + kind: the kinds (shader_constants.h)
// stay below 8, and float holds the code exactly for counts below 2^21.
inline constexpr int kBvhLeafKinds = 8;

// The nodes as the shaders read them (bvh_access.glsl): two RGBA texels per
// node, (box min, first) and (box max, code); the code is 0 for an inner node.
// Each box is rounded outward to float (min down, max up): it still holds
// everything its double box holds.
// At least one node's worth (an empty buffer texture is not allowed everywhere).
std::vector<float> packedBvhNodes(const Bvh& bvh);

// Longest path any traversal stack has to hold: the GLSL stack size
// (BVH_STACK_SIZE) must be at least this. Where the levels left would not
// hold the items even if halved at every level, the builder halves them by
// count instead of by area, so any scene of fewer than 2^31 leaves fits.
inline constexpr int kBvhMaxDepth = 32;

}  // namespace raylab
