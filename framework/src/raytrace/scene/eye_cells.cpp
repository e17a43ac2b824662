#include "eye_cells.h"

#include "cell_cube.h"

#include <algorithm>

namespace raylab {

int EyeCells::longestList() const {
    int longest = 0;
    for (glm::ivec2 c : cells) longest = std::max(longest, c.y);
    return longest;
}

double EyeCells::meanList() const {
    double sum = 0.0;
    int used = 0;
    for (glm::ivec2 c : cells)
        if (c.y > 0) {
            sum += c.y;
            ++used;
        }
    return used > 0 ? sum / used : 0.0;
}

bool eyeCellsSuit(const Scene& scene) {
    return !scene.spheres.empty() && scene.spheres.size() <= kEyeCellMaxSpheres &&
           scene.meshes.empty();
}

EyeCells buildEyeCells(const Scene& scene, glm::vec3 eye, const CellCube& cube) {
    EyeCells out;
    out.eye = eye;
    out.resolution = cube.resolution();
    // The light buffer's margin for a ray running off its line, for a scene
    // reaching as far as the eye: a primary ray starts at the eye exactly,
    // but it crosses the scene in float.
    const double margin =
        rayOffMargin(std::max(sceneReach(scene), 1.01 * glm::length(glm::dvec3(eye))));
    // (cell, sphere) pairs, then sorted by cell with a count per cell: no
    // list per cell to allocate (this runs every frame of a moving camera).
    std::vector<glm::ivec2> pairs;
    std::vector<int> near;
    out.cells.assign(std::size_t(cube.cellCount()), glm::ivec2(0));
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        cube.cellsNear(glm::dvec3(eye), sweptBall(scene.spheres[i]), margin, near);
        for (int c : near) {
            pairs.emplace_back(c, int(i));
            ++out.cells[std::size_t(c)].y;
        }
    }
    int first = 0;
    for (glm::ivec2& c : out.cells) {
        c.x = first;
        first += c.y;
    }
    out.items.resize(pairs.size());
    std::vector<int> filled(out.cells.size(), 0);
    for (glm::ivec2 p : pairs) {  // spheres in ascending order within a cell
        const glm::ivec2 cell = out.cells[std::size_t(p.x)];
        out.items[std::size_t(cell.x + filled[std::size_t(p.x)]++)] = p.y;
    }
    return out;
}

EyeCells buildEyeCells(const Scene& scene, glm::vec3 eye, int resolution) {
    return buildEyeCells(scene, eye, CellCube(resolution));
}

std::vector<int> eyeCellTexels(const EyeCells& cells, int firstItem) {
    std::vector<int> out;
    out.reserve(2 * cells.cells.size());
    for (glm::ivec2 c : cells.cells) out.insert(out.end(), {firstItem + c.x, c.y});
    return out;
}

}  // namespace raylab
