#pragma once
// A light buffer (Haines and Greenberg, "The Light Buffer: A Shadow-Testing
// Accelerator", IEEE CG&A 1986): for each point light, a cube around it
// whose faces are divided into cells, each cell listing the spheres and the
// scene file's triangles seen from the light through it. A shadow ray toward
// the light tests only the objects of the cell its direction falls in,
// instead of walking the whole BVH and every group of triangles
// (framework/shaders/variants/light-buffer/08-full/light_buffer.glsl). The
// cubes and the test of an object against their cells are cell_cube.h's.
//
// Why: shadow rays were about half of a pro frame on llvmpipe, and a BVH
// walk is many steps of reads whose addresses differ between the 8 lock-step
// pixels (docs/bench/README.md, "Round 5"). A cell's list is one read, then
// a short loop.
//
// Conservative, so the picture does not change by one bit: a sphere is in
// every cell whose directions come near its cone as seen from the light,
// with margins for everything that moves a GLSL shadow ray off the exact
// line toward the light (the moving spheres' swing, the ray origin's offset
// off the surface, float rounding, a cell chosen near its border).
// A shading point farther from the origin than `reach` (an infinite floor
// far away: the offset grows with the coordinates) uses the last cell,
// which lists every sphere and triangle. Planes, discs and tori are still
// tested one by one (a disc is cheap; a torus test costs the same whether
// or not a list skips it: llvmpipe runs a loop's body at least once).
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct LightBuffer {
    int resolution = 0;  // cells along a cube face's edge
    // Per cell: (first, count) of its spheres, then of its triangles; cells
    // ordered by light, face, row, column; then the every-object cell.
    std::vector<glm::ivec4> cells;
    std::vector<int> items;  // the lists: sphere and triangle indices
    float reach = 0.0f;      // shading points farther from the origin use every object
    int everyObjectCell() const { return int(cells.size()) - 1; }
    int longestList() const;  // spheres and triangles, of the cells of the cube faces
    double meanList() const;  // the same, on average over the cells that list any
};

// Cells along a face's edge: 128 (0.9 degrees at a face's centre). On pro
// (tools/bench/instructions_per_frame.sh) 64 costs 2% less than 32 and 128
// 1.2% less than 64: shorter lists; the CPU builds pro's 3 x 6 x 128^2
// cells once (4.7 MB of cells).
inline constexpr int kLightBufferResolution = 128;

// Scenes with more spheres keep the BVH for shadow rays: the brute-force
// build below tests every sphere against every cell.
inline constexpr std::size_t kLightBufferMaxSpheres = 1024;

// How finely a triangle is cut for listing (cell_cube.h: 4^3 = 64 pieces).
// On pro (tools/bench/instructions_per_frame.sh) the one ball around a
// cube face's triangle listed it in about as many cells as the whole cube
// covers; 16 pieces cost 2.4% fewer instructions a frame, 64 pieces 2.8%.
// Pro's buffer then takes about 30 ms to build (8 ms with one ball).
inline constexpr int kTriangleSplits = 3;

// Per light of SCENE, per triangle: whether the triangle lies on a closed
// convex shell (convex_shell.h) with the light outside it, on a face whose
// plane has the light behind it by more than ROOM (plus the shell's
// flatness).
// A shadow ray toward the light never needs them. Why: a segment from a
// shading point to a light outside a convex shell that crosses the shell
// leaves it last through a face it runs out of, and the light, further
// along the segment, is in front of that face's plane. So the segment
// always crosses a face turned toward the light too, and a shadow ray stops
// at any blocker. ROOM covers how far the GLSL's ray runs off the exact
// segment (rayOffMargin). Pro's glass cube: of its 12 triangles a light
// sees at most 6. (The GPU side, the same picture to the byte:
// tests/e2e/bvh_images_test.cpp's LightBufferDrawsWhatTheWalkDraws.)
std::vector<std::vector<bool>> facesTurnedAway(const Scene& scene, double room);

// Whether a program for SCENE may use a light buffer (spheres, at most
// kLightBufferMaxSpheres of them, no meshes, at least one light).
bool lightBufferSuits(const Scene& scene);

// The cell of light LIGHT's cube that DIRECTION (from the light, any length
// > 0) falls in: light_buffer.glsl's lightCell (cubeCell, cell_cube.h, on
// the light's cube).
int lightBufferCell(int resolution, int light, glm::vec3 direction);

// Builds the lists for every light of SCENE (in the shaders' units).
// Triangles are listed by the balls of their pieces (cell_cube.h's
// triangleBalls, kTriangleSplits); a closed convex shell's faces turned away
// from the light are not listed at all (facesTurnedAway).
// The cells as the shaders read them: four ints per cell (RGBA texels).
std::vector<int> lightCellTexels(const LightBuffer& buffer);

LightBuffer buildLightBuffer(const Scene& scene, int resolution = kLightBufferResolution);

}  // namespace raylab
