// Cracks between triangles: rays aimed exactly at the edges and corners that
// triangles share must hit at least one of the triangles there. Meshes: a
// triangulated height field (16 x 16 corners, diagonals alternating), the
// mirror of lite.json (a rectangle: two triangles sharing a diagonal) and
// the glass cube of pro.json (12 triangles, closed: every edge shared).
// Rays come from several eyes, near and far; from inside the cube too,
// where the refracted rays travel. Only rays that cross the shared edge
// count (not the mesh's silhouette, where a near miss is a right miss).
// Every hit must be at the right distance, and plain rays (at each
// triangle's centroid, just outside each edge) must hit or miss as they
// should: watertight must not mean "hits too much".
//
// Stage 08's intersectTriangle (float32) by default is the watertight test
// of Woop, Benthin and Wald (2013): no ray may fall through. Lab 05's
// Moller-Trumbore (RAYLAB_NAIVE_NUMERICS) decides each triangle with its own
// rounding and lets some through; its count is printed next to it.
#include "numerics_support.h"

#include "paths.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

using namespace raylab;
using namespace raylab::numerics;
using glm::dvec3;
using glm::vec3;

namespace {

using Tri = std::array<vec3, 3>;

struct TriangleSoup {
    std::string name;
    std::vector<Tri> triangles;
    std::vector<dvec3> eyes;
};

using VertexKey = std::array<float, 3>;
VertexKey key(vec3 v) { return {v.x, v.y, v.z}; }
dvec3 toD(vec3 v) { return dvec3(v); }

TriangleSoup heightField() {
    TriangleSoup m;
    m.name = "height field";
    constexpr int n = 16;
    auto corner = [](int i, int j) {
        const double x = -2.0 + 4.0 * i / (n - 1), z = -2.0 + 4.0 * j / (n - 1);
        const double y =
            0.25 * std::sin(1.7 * x + 0.3) * std::cos(1.3 * z - 0.2) + 0.1 * std::sin(3.1 * x * z);
        return vec3(float(x), float(y), float(z));
    };
    for (int i = 0; i + 1 < n; ++i)
        for (int j = 0; j + 1 < n; ++j) {
            const vec3 a = corner(i, j), b = corner(i + 1, j), c = corner(i + 1, j + 1),
                       d = corner(i, j + 1);
            if ((i + j) % 2 == 0) {
                m.triangles.push_back({a, c, b});
                m.triangles.push_back({a, d, c});
            } else {
                m.triangles.push_back({a, d, b});
                m.triangles.push_back({b, d, c});
            }
        }
    m.eyes = {{0.3, 6.0, 0.5}, {-4.0, 3.0, 5.0}, {7.0, 9.0, -6.0}, {30.0, 60.0, -40.0}};
    return m;
}

// The mirror: lite.json's triangles (its rectangle); the cube: the last 12
// triangles of pro.json (its box; the rectangle comes first).
// A scene triangle's corners as the GPU gets them (rounded once to float).
Tri asFloats(const Triangle& t) {
    return {vec3(t.vertices[0]), vec3(t.vertices[1]), vec3(t.vertices[2])};
}

TriangleSoup mirror() {
    Scene lite = loadScene(projectRoot() / "assets" / "scenes" / "lite.json");
    TriangleSoup m;
    m.name = "mirror";
    for (const Triangle& t : lite.triangles) m.triangles.push_back(asFloats(t));
    m.eyes = {{0.0, 3.0, 9.5}, {-5.0, 1.8, -7.0}, {1.0, 1.0, 2.0}, {40.0, 20.0, 80.0}};
    return m;
}

TriangleSoup glassCube() {
    Scene pro = loadScene(projectRoot() / "assets" / "scenes" / "pro.json");
    TriangleSoup m;
    m.name = "glass cube";
    for (std::size_t i = pro.triangles.size() - 12; i < pro.triangles.size(); ++i)
        m.triangles.push_back(asFloats(pro.triangles[i]));
    dvec3 center(0.0);
    for (const Tri& t : m.triangles)
        for (const vec3& v : t) center += toD(v) / 36.0;
    m.eyes = {center,
              center + dvec3(0.3, -0.2, 0.25),
              {0.0, 6.5, 16.5},
              {0.2, 3.0, 2.6},
              center + dvec3(-30.0, 25.0, 40.0)};
    return m;
}

// A ray and the triangles around the point it is aimed at.
struct AimedRay {
    dvec3 origin, dir;    // float numbers
    double distance = 0;  // to the aimed-at point
    std::vector<int> around;
    bool atCorner = false;
};

// Does the ray from EYE through the edge A-B cross from one of the two
// triangles to the other (their third corners on opposite sides of the plane
// through the eye and the edge)? Else the edge is on the silhouette.
bool crossesEdge(dvec3 eye, dvec3 a, dvec3 b, dvec3 c1, dvec3 c2) {
    const dvec3 m = glm::cross(a - eye, b - eye);
    const double s1 = glm::dot(m, c1 - eye), s2 = glm::dot(m, c2 - eye);
    const double scale = glm::length(m) * std::max(glm::length(c1 - eye), glm::length(c2 - eye));
    return s1 * s2 < 0.0 && std::fabs(s1) > 1e-3 * scale && std::fabs(s2) > 1e-3 * scale;
}

AimedRay aim(dvec3 eye, dvec3 target, std::vector<int> around, bool atCorner) {
    AimedRay r;
    r.origin = dvec3(f32(eye.x), f32(eye.y), f32(eye.z));
    dvec3 d = glm::normalize(target - r.origin);
    r.dir = dvec3(f32(d.x), f32(d.y), f32(d.z));
    r.distance = glm::length(target - r.origin);
    r.around = std::move(around);
    r.atCorner = atCorner;
    return r;
}

std::vector<AimedRay> aimedRays(const TriangleSoup& mesh) {
    // Edges (corner pair, smaller key first) -> the triangles that have them.
    std::map<std::pair<VertexKey, VertexKey>, std::vector<int>> edges;
    std::map<VertexKey, std::vector<int>> corners;
    for (int i = 0; i < int(mesh.triangles.size()); ++i)
        for (int e = 0; e < 3; ++e) {
            VertexKey p = key(mesh.triangles[std::size_t(i)][std::size_t(e)]),
                      q = key(mesh.triangles[std::size_t(i)][std::size_t((e + 1) % 3)]);
            edges[std::minmax(p, q)].push_back(i);
            corners[p].push_back(i);
        }
    auto third = [&](int tri, VertexKey p, VertexKey q) {
        for (const vec3& v : mesh.triangles[std::size_t(tri)])
            if (key(v) != p && key(v) != q) return toD(v);
        return dvec3(0.0);
    };
    auto toVec = [](VertexKey k) { return dvec3(k[0], k[1], k[2]); };
    std::vector<AimedRay> rays;
    constexpr int kSamples = 12;
    for (const dvec3& eye : mesh.eyes) {
        for (const auto& [edge, tris] : edges) {
            if (tris.size() != 2) continue;
            const dvec3 a = toVec(edge.first), b = toVec(edge.second);
            if (!crossesEdge(eye, a, b, third(tris[0], edge.first, edge.second),
                             third(tris[1], edge.first, edge.second)))
                continue;
            for (int k = 0; k < kSamples; ++k) {
                const double s = k % 2 == 0
                                     ? (k / 2 + 1.0) / (kSamples / 2 + 1.0)
                                     : (k + 0.3183) / kSamples;  // exact fractions and others
                rays.push_back(aim(eye, a + s * (b - a), tris, false));
            }
        }
        // A corner surrounded by triangles (every edge at it shared), seen
        // with every edge at it crossing.
        for (const auto& [corner, tris] : corners) {
            bool surrounded = true;
            for (const auto& [edge, owners] : edges)
                if ((edge.first == corner || edge.second == corner) &&
                    (owners.size() != 2 || !crossesEdge(eye, toVec(edge.first), toVec(edge.second),
                                                        third(owners[0], edge.first, edge.second),
                                                        third(owners[1], edge.first, edge.second))))
                    surrounded = false;
            if (surrounded) rays.push_back(aim(eye, toVec(corner), tris, true));
        }
    }
    return rays;
}

// Plain cases, for each triangle alone: a ray at its centroid must hit it
// (at the right distance), rays at points just outside each edge (1e-3 of
// the way from the opposite corner to the edge's middle, beyond it) must
// miss it. Seen from each eye that is not almost in the triangle's plane.
std::vector<AimedRay> plainRays(const TriangleSoup& mesh, std::vector<bool>* outside) {
    std::vector<AimedRay> rays;
    for (const dvec3& eye : mesh.eyes)
        for (int i = 0; i < int(mesh.triangles.size()); ++i) {
            const Tri& t = mesh.triangles[std::size_t(i)];
            const dvec3 a = toD(t[0]), b = toD(t[1]), c = toD(t[2]);
            const dvec3 centroid = (a + b + c) / 3.0;
            const dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
            if (std::fabs(glm::dot(normal, glm::normalize(centroid - eye))) < 0.05)
                continue;  // grazing
            rays.push_back(aim(eye, centroid, {i}, false));
            outside->push_back(false);
            const dvec3 corners[3] = {a, b, c};
            for (int e = 0; e < 3; ++e) {
                const dvec3 middle = (corners[e] + corners[(e + 1) % 3]) / 2.0;
                rays.push_back(
                    aim(eye, middle + 1e-3 * (middle - corners[(e + 2) % 3]), {i}, false));
                outside->push_back(true);
            }
        }
    return rays;
}

struct TriangleFigures {
    int edgeRays = 0, cornerRays = 0, edgeCracks = 0, cornerCracks = 0, nonFinite = 0, wrongT = 0;
    int plainRays = 0, plainWrong = 0;  // centroid missed or a point outside hit
};

std::vector<glm::vec4> runTriangles(const TriangleSoup& mesh, const std::vector<AimedRay>& rays,
                                    bool naive) {
    FunctionSpec spec;
    spec.name = "intersectTriangle";
    spec.includes = {"ray.glsl", "intersect_triangle.glsl"};
    spec.call = "vec4(intersectTriangle(Ray(a0.xyz, a1.xyz), vec3(a0.w, a1.w, a2.w), a2.xyz, "
                "a3.xyz), 0.0, 0.0, 1.0)";
    for (const AimedRay& r : rays)
        for (int tri : r.around) {
            const Tri& t = mesh.triangles[std::size_t(tri)];
            FunctionCase c;
            c.in = {glm::dvec4(r.origin, t[0].x), glm::dvec4(r.dir, t[0].y),
                    glm::dvec4(toD(t[1]), t[0].z), glm::dvec4(toD(t[2]), 0.0)};
            spec.cases.push_back(c);
        }
    std::vector<std::string> defines;
    if (naive) defines.push_back("RAYLAB_NAIVE_NUMERICS");
    return runSolution(spec, "08-full", defines);
}

TriangleFigures measureTriangle(const TriangleSoup& mesh, const std::vector<AimedRay>& rays,
                                bool naive) {
    const std::vector<glm::vec4> got = runTriangles(mesh, rays, naive);
    TriangleFigures f;
    std::vector<bool> outside;
    const std::vector<AimedRay> plain = plainRays(mesh, &outside);
    const std::vector<glm::vec4> plainGot = runTriangles(mesh, plain, naive);
    for (std::size_t i = 0; i < plain.size(); ++i) {
        const float t = plainGot[i].x;
        const bool hit = t > 0.0f && std::isfinite(t);
        if (!std::isfinite(t)) ++f.nonFinite;
        ++f.plainRays;
        if (hit == outside[i] ||
            (hit && std::fabs(double(t) - plain[i].distance) > 1e-4 * plain[i].distance))
            ++f.plainWrong;
    }
    std::size_t next = 0;
    for (const AimedRay& r : rays) {
        bool hit = false;
        for (std::size_t k = 0; k < r.around.size(); ++k, ++next) {
            const float t = got[next].x;
            if (!std::isfinite(t)) ++f.nonFinite;
            if (t > 0.0f && std::isfinite(t)) {
                hit = true;
                if (std::fabs(double(t) - r.distance) > 1e-4 * r.distance) ++f.wrongT;
            }
        }
        (r.atCorner ? f.cornerRays : f.edgeRays) += 1;
        if (!hit) (r.atCorner ? f.cornerCracks : f.edgeCracks) += 1;
    }
    return f;
}

void printTriangle(const std::string& mesh, const char* method, const TriangleFigures& f) {
    std::printf(
        "[ figure   ] %-12s %-16s fell through: %4d of %5d rays at shared edges, %3d of %4d at "
        "shared corners "
        "(hits with a wrong t: %d; plain centroid/outside rays wrong: %d of %d; NaN/Inf: %d)\n",
        mesh.c_str(), method, f.edgeCracks, f.edgeRays, f.cornerCracks, f.cornerRays, f.wrongT,
        f.plainWrong, f.plainRays, f.nonFinite);
}

}  // namespace

TEST(TriangleNumerics, WatertightTestHasNoCracksAndMollerTrumboreHas) {
    ensureGlContext();
    int naiveCracks = 0;
    for (const TriangleSoup& mesh : {heightField(), mirror(), glassCube()}) {
        SCOPED_TRACE(mesh.name);
        const std::vector<AimedRay> rays = aimedRays(mesh);
        const TriangleFigures robust = measureTriangle(mesh, rays, false);
        const TriangleFigures naive = measureTriangle(mesh, rays, true);
        printTriangle(mesh.name, "watertight", robust);
        printTriangle(mesh.name, "Moller-Trumbore", naive);
        EXPECT_GT(robust.edgeRays, 10) << "every mesh must be seen across shared edges";
        EXPECT_EQ(robust.edgeCracks + robust.cornerCracks, 0);
        EXPECT_EQ(robust.nonFinite, 0);
        EXPECT_EQ(robust.wrongT, 0);
        EXPECT_EQ(robust.plainWrong, 0);
        naiveCracks += naive.edgeCracks + naive.cornerCracks;
    }
    // The difference the default makes.
    EXPECT_GT(naiveCracks, 0);
}
