// The light buffer (framework/src/raytrace/scene/light_buffer.h): every
// sphere and triangle a shadow ray can meet must be in the lists of the cell
// the ray's direction falls in, or the shadow-ray variant would draw light where the
// BVH walk draws shadow - except a closed convex shell's faces turned away
// from the light (facesTurnedAway), where the ray must meet a listed face
// of the same shell instead. Checked with shadow rays built the way
// light_visibility.glsl builds them (float direction, origin moved off the
// surface by up to ray_offset.glsl's bound) against an exact segment-sphere
// test in double (segment-sphere, segment-triangle). The GPU side (the same picture as the walk,
// bit for bit) is tests/e2e/bvh_images_test.cpp's LightBufferDrawsWhatTheWalkDraws.
#include "convex_shell.h"
#include "light_buffer.h"
#include "paths.h"
#include "scene.h"
#include "scene_transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

using namespace raylab;

namespace {

Scene lightBufferScene(const char* name) {
    return loadScene(projectRoot() / "assets/scenes" / (std::string(name) + ".json"));
}

// Does the segment from O along unit D, 0 <= t <= maxT, come within R of C?
// (A little more than the GLSL's test finds: a stricter check of the lists.)
bool segmentMeetsSphere(glm::dvec3 o, glm::dvec3 d, double maxT, glm::dvec3 c, double r) {
    const double t = std::clamp(glm::dot(c - o, d), 0.0, maxT);
    return glm::length(o + t * d - c) <= r * (1.0 + 1e-6);
}

// Does the segment from O along unit D, 0 <= t <= maxT, cross triangle
// (A, B, C)? Moeller and Trumbore's test in double, with the triangle's
// edges widened a little (a stricter check).
bool segmentMeetsTriangle(glm::dvec3 o, glm::dvec3 d, double maxT, glm::dvec3 a, glm::dvec3 b,
                          glm::dvec3 c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-300) return false;
    const glm::dvec3 s = o - a, q = glm::cross(s, e1);
    const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
    const double slack = 1e-6;
    return u >= -slack && v >= -slack && u + v <= 1.0 + slack && t >= 0.0 && t <= maxT;
}

struct LightBufferAudit {
    long blockedRays = 0;  // (ray, object) pairs where the object blocks the ray
    long missing = 0;      // ... and the ray's cell does not list it (nor its shell's other faces)
    long blockedByTriangles = 0;
    long leftOutFaces = 0;  // ... a shell's face the list left out, the ray meeting a listed one
};

// Per triangle of SCENE: the closed convex shell it belongs to, or -1.
std::vector<int> shellOfTriangle(const Scene& scene, const std::vector<ConvexShell>& shells) {
    std::vector<int> shellOf(scene.triangles.size(), -1);
    for (std::size_t k = 0; k < shells.size(); ++k)
        for (int t : shells[k].triangles) shellOf[std::size_t(t)] = int(k);
    return shellOf;
}

// A point well inside the shell, at random (a shading point on the torus
// in pro's cube, or on a face seen from inside).
glm::dvec3 insideShell(const ConvexShell& shell, std::mt19937& rng) {
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& p : shell.points) centre += p;
    centre /= double(shell.points.size());
    double room = 1e300;
    for (std::size_t k = 0; k < shell.points.size(); ++k)
        room = std::min(room, -planeDistance(shell, k, centre));
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    glm::dvec3 v;
    do v = {unit(rng), unit(rng), unit(rng)};
    while (glm::length(v) > 1.0);
    return centre + 0.95 * room * v;
}

// Shadow rays from points on the spheres and anywhere in the scene's reach
// toward every light, with the spheres anywhere on their swing.
LightBufferAudit auditLightBuffer(const Scene& scene, const LightBuffer& buffer,
                                  int lookupResolution, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto randomDirection = [&] {
        glm::dvec3 v;
        do v = {unit(rng), unit(rng), unit(rng)};
        while (glm::length(v) > 1.0 || glm::length(v) < 1e-3);
        return glm::normalize(v);
    };
    LightBufferAudit a;
    const double reach = buffer.reach;
    const std::vector<ConvexShell> shells = convexShells(scene);
    const std::vector<int> shellOf = shellOfTriangle(scene, shells);
    for (int sample = 0; sample < 20000; ++sample) {
        // Half the points on a sphere's surface (where shadows are cast on
        // neighbours), a quarter anywhere within the reach, a quarter inside
        // the shells if any (else within the reach too).
        glm::dvec3 p;
        if (sample % 2 == 0) {
            const Sphere& s = scene.spheres[std::size_t(sample / 2) % scene.spheres.size()];
            p = glm::dvec3(s.center) + double(s.radius) * randomDirection();
        } else if (sample % 4 == 3 && !shells.empty()) {
            p = insideShell(shells[std::size_t(sample / 4) % shells.size()], rng);
        } else {
            p = reach * std::cbrt(0.5 + 0.5 * unit(rng)) * randomDirection();
        }
        // ray_offset.glsl's offset: up to 256 float steps per coordinate.
        const glm::dvec3 off = (3.05e-5 * glm::length(p) + 1.5e-5) * unit(rng) * randomDirection();
        const glm::vec3 point(p);
        const double time = 10.0 * (0.5 + 0.5 * unit(rng));
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            const glm::vec3 toLight = glm::vec3(scene.lights[l].position) - point;
            const float distance = glm::length(toLight);
            if (distance <= 0.0f) continue;
            const glm::vec3 dir = toLight / distance;  // as the GLSL forms it
            const glm::vec3 origin = glm::vec3(glm::dvec3(point) + off);
            const int cell = glm::length(origin) > buffer.reach
                                 ? buffer.everyObjectCell()
                                 : lightBufferCell(lookupResolution, int(l), -dir);
            const glm::ivec4 list = buffer.cells.at(std::size_t(cell));
            const auto first = buffer.items.begin() + list.x, end = first + list.y;
            const auto firstTriangle = buffer.items.begin() + list.z,
                       endTriangle = firstTriangle + list.w;
            std::vector<int> blocking;
            std::vector<bool> listed;
            for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
                const auto& v = scene.triangles[i].vertices;
                if (!segmentMeetsTriangle(glm::dvec3(origin), glm::dvec3(dir), distance, v[0], v[1],
                                          v[2]))
                    continue;
                ++a.blockedRays;
                ++a.blockedByTriangles;
                blocking.push_back(int(i));
                listed.push_back(std::find(firstTriangle, endTriangle, int(i)) != endTriangle);
            }
            for (std::size_t k = 0; k < blocking.size(); ++k) {
                if (listed[k]) continue;
                const int shell = shellOf[std::size_t(blocking[k])];
                bool covered = false;
                for (std::size_t j = 0; j < blocking.size() && shell >= 0; ++j)
                    covered = covered || (listed[j] && shellOf[std::size_t(blocking[j])] == shell);
                ++(covered ? a.leftOutFaces : a.missing);
            }
            for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
                const Sphere& s = scene.spheres[i];
                const glm::dvec3 centre = s.center + s.motion.offsetAt(float(time));
                if (!segmentMeetsSphere(glm::dvec3(origin), glm::dvec3(dir), distance, centre,
                                        s.radius))
                    continue;
                ++a.blockedRays;
                if (std::find(first, end, int(i)) == end) ++a.missing;
            }
        }
    }
    return a;
}

void expectConservative(const char* name, const Scene& scene) {
    const LightBuffer buffer = buildLightBuffer(scene);
    const LightBufferAudit a = auditLightBuffer(scene, buffer, buffer.resolution, 1);
    std::printf("[ figure ] %s: %d lights x 6 faces x %d^2 cells; a list that is not empty holds "
                "%.2f objects on average, %d at most (of %zu spheres, %zu triangles); %ld blocked "
                "shadow rays (%ld by triangles, %ld by a shell's face left out of a list that "
                "holds another face the ray meets), %ld missing from their cell\n",
                name, int(scene.lights.size()), buffer.resolution, buffer.meanList(),
                buffer.longestList(), scene.spheres.size(), scene.triangles.size(), a.blockedRays,
                a.blockedByTriangles, a.leftOutFaces, a.missing);
    EXPECT_GT(a.blockedRays, 1000) << "too few blocked rays to say anything";
    if (!scene.triangles.empty()) { EXPECT_GT(a.blockedByTriangles, 100); }
    EXPECT_EQ(a.missing, 0) << "a shadow ray's cell lacks a sphere that blocks it";
    if (!convexShells(scene).empty()) { EXPECT_GT(a.leftOutFaces, 0) << "no face left out"; }
}

}  // namespace

TEST(LightBuffer, EveryBlockingSphereIsInTheRaysCell) {
    expectConservative("pro", lightBufferScene("pro"));
    expectConservative("lite", lightBufferScene("lite"));
}

// The margins are shares of the scene's size and distance from the origin,
// so they hold for a scene resized or moved far away (the renderers draw
// those in a standard frame, but the buffer does not rely on it).
TEST(LightBuffer, EveryBlockingSphereIsInTheRaysCellAtAnyScaleAndPlace) {
    const Scene lightBufferPro = lightBufferScene("pro");
    for (double scale : {1e-4, 1e6}) {
        SceneTransform t;
        t.scale = scale;
        expectConservative(("pro x " + std::to_string(scale)).c_str(),
                           transformScene(lightBufferPro, t));
    }
    SceneTransform far;
    far.offset = glm::dvec3(1e5, 0.0, 0.0);
    expectConservative("pro moved by 1e5", transformScene(lightBufferPro, far));
}

// The lists are short: that is the point of the buffer (pro's BVH walk
// visits about 20 nodes per shadow ray).
TEST(LightBuffer, ProsListsAreShort) {
    const Scene lightBufferPro = lightBufferScene("pro");
    const auto start = std::chrono::steady_clock::now();
    const LightBuffer buffer = buildLightBuffer(lightBufferPro);
    std::printf("[ figure ] pro's light buffer built in %.1f ms (a figure, not a check)\n",
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
    EXPECT_LT(buffer.meanList(), 6.0);
    EXPECT_EQ(buffer.cells.back().y, 110) << "the last cell lists every sphere";
    EXPECT_EQ(buffer.cells.back().w, 14) << "... and every triangle";
}

// The audit can fail: lists built for spheres 10% smaller, for triangles
// moved 3 along x, leaving out a shell's faces the light sees instead of
// those turned away, or looked up with the wrong grid, miss blockers.
TEST(LightBuffer, AWrongBufferIsCaught) {
    const Scene lightBufferPro = lightBufferScene("pro");
    Scene smaller = lightBufferPro;
    for (Sphere& s : smaller.spheres) s.radius *= 0.9;
    const LightBufferAudit shrunk =
        auditLightBuffer(lightBufferPro, buildLightBuffer(smaller), kLightBufferResolution, 2);
    std::printf("[ figure ] lists of spheres 10%% smaller: %ld of %ld blocked rays missing\n",
                shrunk.missing, shrunk.blockedRays);
    EXPECT_GT(shrunk.missing, 0);
    Scene movedTriangles = lightBufferPro;
    for (Triangle& t : movedTriangles.triangles)
        for (glm::dvec3& v : t.vertices) v.x += 3.0;
    const LightBufferAudit triangles = auditLightBuffer(
        lightBufferPro, buildLightBuffer(movedTriangles), kLightBufferResolution, 4);
    std::printf("[ figure ] lists of triangles moved 3 along x: %ld of %ld blocked rays missing\n",
                triangles.missing, triangles.blockedRays);
    EXPECT_GT(triangles.missing, 0);
    // The cube turned inside out through its centre, each triangle onto the
    // face across: the lists leave out the faces the light sees.
    Scene swapped = lightBufferPro;
    for (const ConvexShell& shell : convexShells(lightBufferPro)) {
        glm::dvec3 centre(0.0);
        for (int t : shell.triangles)
            for (const glm::dvec3& v : lightBufferPro.triangles[std::size_t(t)].vertices)
                centre += v;
        centre /= 3.0 * double(shell.triangles.size());
        for (int t : shell.triangles) {
            auto& v = swapped.triangles[std::size_t(t)].vertices;
            for (glm::dvec3& corner : v) corner = 2.0 * centre - corner;
            std::swap(v[1], v[2]);  // still counter-clockwise from outside
        }
    }
    ASSERT_EQ(convexShells(swapped).size(), convexShells(lightBufferPro).size());
    const LightBufferAudit faces =
        auditLightBuffer(lightBufferPro, buildLightBuffer(swapped), kLightBufferResolution, 5);
    std::printf("[ figure ] lists that leave out the faces the lights see: %ld of %ld blocked "
                "rays missing\n",
                faces.missing, faces.blockedRays);
    EXPECT_GT(faces.missing, 0);
    const LightBuffer buffer = buildLightBuffer(lightBufferPro);
    const LightBufferAudit grid =
        auditLightBuffer(lightBufferPro, buffer, kLightBufferResolution / 2, 3);
    std::printf("[ figure ] lists looked up on a grid half as fine: %ld of %ld missing\n",
                grid.missing, grid.blockedRays);
    EXPECT_GT(grid.missing, 0);
}

TEST(LightBuffer, OnlyForScenesItSuits) {
    EXPECT_TRUE(lightBufferSuits(lightBufferScene("pro")));
    EXPECT_FALSE(lightBufferSuits(lightBufferScene("mesh"))) << "mesh triangles stay in the BVH";
    Scene none = lightBufferScene("lite");
    none.spheres.clear();
    EXPECT_FALSE(lightBufferSuits(none));
}
