#include "adjacency.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace raylab {

namespace {

// One side of an edge as a triangle sees it: the edge from B to C in the
// triangle's winding, and the third corner A.
struct HalfEdge {
    std::uint32_t a, b, c;
    std::uint32_t fromPos, toPos;  // position ids of B and C
    bool used = false;
};

bool degenerate(const Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                const std::vector<std::uint32_t>& pos) {
    if (pos[a] == pos[b] || pos[b] == pos[c] || pos[a] == pos[c]) return true;
    glm::dvec3 e1 = glm::dvec3(m.positions[b]) - glm::dvec3(m.positions[a]);
    glm::dvec3 e2 = glm::dvec3(m.positions[c]) - glm::dvec3(m.positions[a]);
    // Zero area, or so thin that float cannot give it a normal.
    double area2 = glm::length(glm::cross(e1, e2));
    double scale = std::max(glm::dot(e1, e1), glm::dot(e2, e2));
    return !(area2 > 1e-12 * scale);
}

}  // namespace

EdgeAdjacency buildEdgeAdjacency(const Mesh& mesh) {
    // Position ids: vertices at exactly one position share an id.
    std::vector<std::uint32_t> pos(mesh.positions.size());
    {
        std::map<std::tuple<float, float, float>, std::uint32_t> ids;
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::vec3& p = mesh.positions[i];
            pos[i] = ids.emplace(std::make_tuple(p.x, p.y, p.z), std::uint32_t(ids.size()))
                         .first->second;
        }
    }
    EdgeAdjacency out;
    // Half-edges grouped by their undirected edge, in triangle order.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<HalfEdge>> edges;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order;  // first appearance
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        if (degenerate(mesh, v[0], v[1], v[2], pos)) {
            ++out.degenerateTriangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            HalfEdge h{v[(k + 2) % 3], v[k], v[(k + 1) % 3], pos[v[k]], pos[v[(k + 1) % 3]]};
            auto key = std::minmax(h.fromPos, h.toPos);
            auto& list = edges[key];
            if (list.empty()) order.push_back(key);
            list.push_back(h);
        }
    }
    auto emit = [&](const HalfEdge& h, std::uint32_t d) {
        out.indices.insert(out.indices.end(), {h.a, h.b, h.c, d});
    };
    for (const auto& key : order) {
        std::vector<HalfEdge>& list = edges[key];
        if (list.size() > 2) ++out.nonManifoldEdges;
        // Pair each side with the first unused side running the other way.
        for (std::size_t i = 0; i < list.size(); ++i) {
            if (list[i].used) continue;
            list[i].used = true;
            std::size_t j = i + 1;
            while (j < list.size() && (list[j].used || list[j].fromPos != list[i].toPos)) ++j;
            if (j < list.size()) {
                list[j].used = true;
                emit(list[i], list[j].a);
                ++out.interiorEdges;
            } else {
                emit(list[i], list[i].a);
                ++out.boundaryEdges;
            }
        }
    }
    return out;
}

}  // namespace raylab
