#include "mesh.h"

#include "error.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace raylab {

std::size_t Mesh::bufferBytes() const {
    return positions.size() * sizeof(glm::vec3) + normals.size() * sizeof(glm::vec3) +
           uvs.size() * sizeof(glm::vec2) + indices.size() * sizeof(std::uint32_t);
}

namespace {
bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}  // namespace

void computeSmoothNormals(Mesh& mesh) {
    // Vertices at one position share a normal: key them by exact position.
    std::map<std::tuple<float, float, float>, glm::dvec3> byPosition;
    auto key = [&](std::uint32_t i) {
        const glm::vec3& p = mesh.positions[i];
        return std::make_tuple(p.x, p.y, p.z);
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        // The cross product's length is twice the area: the weighting comes free.
        glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[b] - mesh.positions[a]),
                                  glm::dvec3(mesh.positions[c] - mesh.positions[a]));
        for (std::uint32_t v : {a, b, c}) byPosition[key(v)] += n;
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 1, 0));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        auto it = byPosition.find(key(std::uint32_t(i)));
        if (it == byPosition.end()) continue;
        double length = glm::length(it->second);
        if (length > 0.0) mesh.normals[i] = glm::vec3(it->second / length);
    }
}

void computeBoxUvs(Mesh& mesh) {
    Mesh out;
    out.name = mesh.name;
    // (old vertex, axis) -> new vertex: a vertex on a seam is split, one copy per side.
    std::map<std::pair<std::uint32_t, int>, std::uint32_t> copyOf;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t* tri = &mesh.indices[t];
        const glm::vec3 n = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                       mesh.positions[tri[2]] - mesh.positions[tri[0]]);
        const glm::vec3 a = glm::abs(n);
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        for (int k = 0; k < 3; ++k) {
            auto [it, added] =
                copyOf.emplace(std::make_pair(tri[k], axis), std::uint32_t(out.positions.size()));
            if (added) {
                const glm::vec3& p = mesh.positions[tri[k]];
                // The two other axes, in an order that keeps the picture unmirrored per side.
                const glm::vec2 uv = axis == 0   ? glm::vec2(p.z, p.y)
                                     : axis == 1 ? glm::vec2(p.x, p.z)
                                                 : glm::vec2(p.x, p.y);
                out.positions.push_back(p);
                out.normals.push_back(mesh.normals[tri[k]]);
                out.uvs.push_back(uv / kBoxUvSpan);
            }
            out.indices.push_back(it->second);
        }
    }
    mesh = std::move(out);
}

void computeSphericalUvs(Mesh& mesh) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    mesh.uvs.resize(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        glm::dvec3 d = glm::dvec3(mesh.positions[i] - centre);
        double r = glm::length(d);
        if (r == 0.0) {
            mesh.uvs[i] = glm::vec2(0.5f);
            continue;
        }
        d /= r;
        mesh.uvs[i] = glm::vec2(float(0.5 + std::atan2(d.x, d.z) / (2.0 * M_PI)),
                                float(std::acos(std::clamp(d.y, -1.0, 1.0)) / M_PI));
    }
}

void validateMesh(const Mesh& mesh) {
    auto fail = [&](const std::string& what) { throw Error(mesh.name + ": " + what); };
    if (mesh.positions.empty() || mesh.indices.empty()) fail("the mesh has no triangles");
    if (mesh.indices.size() % 3 != 0) fail("the index count is not a multiple of 3");
    // 32-bit indices, and draw counts in a GLsizei (the adjacency buffer
    // holds four indices per edge: twice the triangles' indices).
    if (mesh.positions.size() > std::size_t(INT32_MAX) ||
        mesh.indices.size() > std::size_t(INT32_MAX) / 2)
        fail("too large: at most 2^31 vertices and 2^30 indices");
    if (mesh.normals.size() != mesh.positions.size() || mesh.uvs.size() != mesh.positions.size())
        fail("every vertex needs a normal and a texture coordinate");
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.positions.size())
            fail("index " + std::to_string(i) + " is past the last vertex (" +
                 std::to_string(mesh.positions.size()) + " vertices)");
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        if (!finite(mesh.positions[i]) || !finite(mesh.normals[i]) ||
            !std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
            fail("vertex " + std::to_string(i) + " has a value that is not a finite number");
}

BoundingSphere boundingSphere(const Mesh& mesh) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    BoundingSphere b;
    b.centre = 0.5f * (lo + hi);
    for (const glm::vec3& p : mesh.positions)
        b.radius = std::max(b.radius, glm::length(p - b.centre));
    return b;
}

}  // namespace raylab
