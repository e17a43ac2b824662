#include "light_buffer.h"

#include "cell_cube.h"
#include "convex_shell.h"
#include "float_rounding.h"

#include <algorithm>
#include <cmath>

namespace raylab {

int LightBuffer::longestList() const {
    int longest = 0;
    for (std::size_t c = 0; c + 1 < cells.size(); ++c)
        longest = std::max(longest, cells[c].y + cells[c].w);
    return longest;
}

double LightBuffer::meanList() const {
    double sum = 0.0;
    int used = 0;
    for (std::size_t c = 0; c + 1 < cells.size(); ++c)
        if (cells[c].y + cells[c].w > 0) {
            sum += cells[c].y + cells[c].w;
            ++used;
        }
    return used > 0 ? sum / used : 0.0;
}

bool lightBufferSuits(const Scene& scene) {
    return !scene.spheres.empty() && scene.spheres.size() <= kLightBufferMaxSpheres &&
           scene.meshes.empty() && !scene.lights.empty();
}

int lightBufferCell(int resolution, int light, glm::vec3 d) {
    return light * 6 * resolution * resolution + cubeCell(resolution, d);
}

std::vector<std::vector<bool>> facesTurnedAway(const Scene& scene, double room) {
    std::vector<std::vector<bool>> away(scene.lights.size(),
                                        std::vector<bool>(scene.triangles.size(), false));
    for (const ConvexShell& shell : convexShells(scene)) {
        const double r = room + shell.flat;
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            const glm::dvec3 light = scene.lights[l].position;
            double outside = -1e300;
            for (std::size_t k = 0; k < shell.triangles.size(); ++k)
                outside = std::max(outside, planeDistance(shell, k, light));
            if (outside < r) continue;  // the light is inside, or too near to say
            for (std::size_t k = 0; k < shell.triangles.size(); ++k)
                if (planeDistance(shell, k, light) <= -r)
                    away[l][std::size_t(shell.triangles[k])] = true;
        }
    }
    return away;
}

LightBuffer buildLightBuffer(const Scene& scene, int resolution) {
    LightBuffer buffer;
    buffer.resolution = resolution;
    const double reach = sceneReach(scene);
    buffer.reach = floatBelow(reach);  // rounded inward: a point near the edge uses every object
    const double margin = rayOffMargin(reach);
    const CellCube cube(resolution);
    const int perLight = cube.cellCount();

    const std::size_t cellCount = std::size_t(perLight) * scene.lights.size();
    std::vector<std::vector<int>> sphereLists(cellCount), triangleLists(cellCount);
    std::vector<int> near;
    const std::vector<std::vector<bool>> away = facesTurnedAway(scene, margin);
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const glm::dvec3 light = scene.lights[l].position;
        // Adds I to the lists of the cells of light L's cube whose directions
        // come near BALL, grown by how far a shadow ray may run off the line
        // through the light.
        auto list = [&](const CellBall& ball, int i, std::vector<std::vector<int>>& lists) {
            cube.cellsNear(light, ball, margin, near);
            for (int c : near) lists[l * std::size_t(perLight) + std::size_t(c)].push_back(i);
        };
        for (std::size_t i = 0; i < scene.spheres.size(); ++i)
            list(sweptBall(scene.spheres[i]), int(i), sphereLists);
        // A triangle by the balls of its pieces: the cells that any piece
        // comes near, each once.
        std::vector<int> cells;
        for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
            if (away[l][i]) continue;
            cells.clear();
            for (const CellBall& piece : triangleBalls(scene.triangles[i], kTriangleSplits)) {
                cube.cellsNear(light, piece, margin, near);
                cells.insert(cells.end(), near.begin(), near.end());
            }
            std::sort(cells.begin(), cells.end());
            cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
            for (int c : cells)
                triangleLists[l * std::size_t(perLight) + std::size_t(c)].push_back(int(i));
        }
    }
    auto append = [&](const std::vector<int>& list) {
        const glm::ivec2 at(int(buffer.items.size()), int(list.size()));
        buffer.items.insert(buffer.items.end(), list.begin(), list.end());
        return at;
    };
    for (std::size_t c = 0; c < cellCount; ++c)
        buffer.cells.emplace_back(append(sphereLists[c]), append(triangleLists[c]));
    std::vector<int> everySphere(scene.spheres.size()), everyTriangle(scene.triangles.size());
    for (std::size_t i = 0; i < everySphere.size(); ++i) everySphere[i] = int(i);
    for (std::size_t i = 0; i < everyTriangle.size(); ++i) everyTriangle[i] = int(i);
    buffer.cells.emplace_back(append(everySphere), append(everyTriangle));
    return buffer;
}

std::vector<int> lightCellTexels(const LightBuffer& buffer) {
    std::vector<int> cells;
    cells.reserve(4 * buffer.cells.size());
    for (glm::ivec4 c : buffer.cells) cells.insert(cells.end(), {c.x, c.y, c.z, c.w});
    return cells;
}

}  // namespace raylab
