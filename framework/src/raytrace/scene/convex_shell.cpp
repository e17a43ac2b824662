#include "convex_shell.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

namespace raylab {

namespace {

using Corner = std::array<double, 3>;  // a corner's exact coordinates: shared corners compare equal

Corner corner(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// The triangles of SCENE in groups that share corners (union-find).
std::vector<std::vector<int>> connectedTriangles(const Scene& scene) {
    const int n = int(scene.triangles.size());
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
        while (parent[std::size_t(i)] != i) i = parent[std::size_t(i)];
        return i;
    };
    std::map<Corner, int> firstWithCorner;
    for (int i = 0; i < n; ++i)
        for (const glm::dvec3& v : scene.triangles[std::size_t(i)].vertices) {
            auto [at, added] = firstWithCorner.emplace(corner(v), i);
            if (!added) parent[std::size_t(find(i))] = find(at->second);
        }
    std::map<int, std::vector<int>> groups;
    for (int i = 0; i < n; ++i) groups[find(i)].push_back(i);
    std::vector<std::vector<int>> out;
    for (auto& [root, members] : groups) out.push_back(std::move(members));
    return out;
}

// The group as a closed convex shell, or false.
bool asShell(const Scene& scene, const std::vector<int>& group, ConvexShell& shell) {
    std::map<std::pair<Corner, Corner>, int> edges;
    std::vector<glm::dvec3> corners;
    for (int i : group)
        for (int k = 0; k < 3; ++k) {
            const auto& v = scene.triangles[std::size_t(i)].vertices;
            Corner a = corner(v[std::size_t(k)]), b = corner(v[std::size_t((k + 1) % 3)]);
            if (b < a) std::swap(a, b);
            ++edges[{a, b}];
            corners.emplace_back(v[std::size_t(k)]);
        }
    if (group.size() < 4) return false;
    for (const auto& [edge, count] : edges)
        if (count != 2) return false;  // open, or more than two faces on an edge
    glm::dvec3 lo = corners[0], hi = corners[0], centre(0.0);
    for (glm::dvec3 c : corners) {
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
        centre += c / double(corners.size());
    }
    shell.triangles = group;
    shell.size = glm::length(hi - lo);
    shell.flat = 1e-6 * (shell.size + std::max(glm::length(lo), glm::length(hi)));
    for (int i : group) {
        const auto& v = scene.triangles[std::size_t(i)].vertices;
        const glm::dvec3 a(v[0]), b(v[1]), c(v[2]);
        glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) <= 1e-12 * shell.size * shell.size) return false;  // degenerate
        n = glm::normalize(n);
        if (glm::dot(n, centre - a) > 0.0) n = -n;  // outward
        for (glm::dvec3 p : corners)
            if (glm::dot(n, p - a) > shell.flat) return false;  // a corner outside: not convex
        shell.normals.push_back(n);
        shell.points.push_back(a);
    }
    return true;
}

}  // namespace

std::vector<ConvexShell> convexShells(const Scene& scene) {
    std::vector<ConvexShell> shells;
    for (const std::vector<int>& group : connectedTriangles(scene)) {
        ConvexShell s;
        if (asShell(scene, group, s)) shells.push_back(std::move(s));
    }
    return shells;
}

double planeDistance(const ConvexShell& shell, std::size_t i, glm::dvec3 p) {
    return glm::dot(shell.normals[i], p - shell.points[i]);
}

}  // namespace raylab
