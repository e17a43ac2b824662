#pragma once
// The eye's cells: a cube of direction cells around the eye (cell_cube.h),
// each listing the spheres a ray from the eye through it may meet - an item
// buffer (Weghorst, Hooper and Greenberg, "Improved Computational Methods
// for Ray Tracing", ACM TOG 1984, who drew each pixel's first object ahead
// of tracing), coarsened to lists so that it stays exact. A primary ray
// tests the spheres of its cell instead of walking the BVH from the root
// (framework/shaders/variants/eye-cells/08-full/test_spheres.glsl).
//
// Why: on llvmpipe a BVH walk is many steps of reads whose addresses differ
// between the 8 lock-step pixels; a primary ray's walk was about a tenth of
// a pro frame (docs/bench/README.md, "Round 6"). A cell's list is one read,
// then one short loop - the walk's leaf loop, given the list as its leaf.
//
// Conservative, so the picture does not change by one bit: a sphere is in
// every cell whose directions come near its cone as seen from the eye, over
// its whole swing, with the light buffer's margins. Rebuilt whenever the eye
// moves (a turning camera keeps its cells: they cover every direction).
#include "cell_cube.h"
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct EyeCells {
    glm::vec3 eye{0.0f};  // the point the cube is built around: the eye the GPU gets (uEye)
    int resolution = 0;   // cells along a face's edge
    // Per cell (numbered as cubeCell numbers them): (first, count) of its spheres in `items`.
    std::vector<glm::ivec2> cells;
    std::vector<int> items;  // the lists: sphere indices
    int longestList() const;
    double meanList() const;  // over the cells that list any
};

// Cells along a face's edge. (Measured in docs/bench/README.md, "Round 6".)
inline constexpr int kEyeCellResolution = 64;

// Scenes with more spheres keep the walk for primary rays: the build below
// tests every sphere against the cells of every face it may be seen on,
// again whenever the eye moves.
inline constexpr std::size_t kEyeCellMaxSpheres = 1024;

// Whether a program for SCENE may use eye cells (spheres, at most
// kEyeCellMaxSpheres of them, no meshes: the cells list spheres only, and a
// tree with mesh triangles would need them listed too).
bool eyeCellsSuit(const Scene& scene);

// Builds the lists of SCENE's spheres (in the shaders' units) for rays from
// EYE, on CUBE's cells (a renderer keeps its cube: the cells' geometry is the
// same for every eye).
EyeCells buildEyeCells(const Scene& scene, glm::vec3 eye, const CellCube& cube);
// The cells as the shaders read them: two ints per cell, (first, count),
// with `first` moved by FIRSTITEM: the lists sit in the tree's item texture
// after its FIRSTITEM items.
std::vector<int> eyeCellTexels(const EyeCells& cells, int firstItem);
EyeCells buildEyeCells(const Scene& scene, glm::vec3 eye, int resolution = kEyeCellResolution);

}  // namespace raylab
