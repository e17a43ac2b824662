#pragma once
// A light buffer (Haines and Greenberg, "The Light Buffer: A Shadow-Testing
// Accelerator", IEEE CG&A 1986): for each point light, a cube around it
// whose faces are divided into cells, each cell listing the spheres seen
// from the light through it. A shadow ray toward the light tests only the
// spheres of the cell its direction falls in, instead of walking the whole
// BVH (framework/shaders/variants/light-buffer/08-full/light_buffer.glsl).
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
// which lists every sphere. Planes, discs, triangles and tori are still
// tested one by one (find_closest.glsl's testOthers).
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct LightBuffer {
    int resolution = 0;             // cells along a cube face's edge
    std::vector<glm::ivec2> cells;  // (first, count) of light, face, row, column; then the
                                    // every-sphere cell
    std::vector<int> items;         // the lists: sphere indices
    float reach = 0.0f;             // shading points farther from the origin use every sphere
    int everySphereCell() const { return int(cells.size()) - 1; }
    int longestList() const;  // of the cells of the cube faces
    double meanList() const;  // the same, on average
};

// Cells along a face's edge: 32 (2.8 degrees at a face's centre). Measured on
// pro with tools/bench/instructions_per_frame.sh: see docs/bench/README.md.
inline constexpr int kLightBufferResolution = 32;

// Scenes with more spheres keep the BVH for shadow rays: the brute-force
// build below tests every sphere against every cell.
inline constexpr std::size_t kLightBufferMaxSpheres = 1024;

// Whether a program for SCENE may use a light buffer (spheres, at most
// kLightBufferMaxSpheres of them, no meshes, at least one light).
bool lightBufferSuits(const Scene& scene);

// The cell of light LIGHT's cube that DIRECTION (from the light, any length
// > 0) falls in: the same float arithmetic as light_buffer.glsl's lightCell.
int lightBufferCell(int resolution, int light, glm::vec3 direction);

// The unit direction through the middle of cell (FACE, ROW, COLUMN) and the
// largest angle between it and a corner of the cell, in radians.
glm::dvec3 lightBufferCellCentre(int resolution, int face, int row, int column);
double lightBufferCellRadius(int resolution, int face, int row, int column);

// Builds the lists for every light of SCENE (in the shaders' units).
LightBuffer buildLightBuffer(const Scene& scene, int resolution = kLightBufferResolution);

}  // namespace raylab
