#include "triangle_groups.h"

namespace raylab {

std::vector<TriangleGroup> triangleGroups(const Scene& scene) {
    std::vector<TriangleGroup> groups;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        const bool joins = !groups.empty() && groups.back().count < kTriangleGroupMax &&
                           scene.triangles[i - 1].material == t.material;
        if (!joins) groups.push_back({int(i), 0, t.vertices[0], t.vertices[0]});
        TriangleGroup& g = groups.back();
        ++g.count;
        for (const glm::dvec3& p : t.vertices) {
            g.lo = glm::min(g.lo, p);
            g.hi = glm::max(g.hi, p);
        }
    }
    return groups;
}

}  // namespace raylab
