// The eye's cells (framework/src/raytrace/scene/eye_cells.h): every sphere a
// ray from the eye can meet must be in the list of the cell its direction
// falls in, or the eye-cells variant would draw the background or a sphere
// behind where the BVH walk draws the nearer one. Checked with rays built the
// way the GLSL builds them (float direction, from the eye exactly) against an
// exact ray-sphere test in double. The GPU side (the same picture as the
// walk, bit for bit) is tests/e2e/bvh_images_test.cpp's EyeCellsDrawWhatTheWalkDraws.
#include "cell_cube.h"
#include "eye_cells.h"
#include "paths.h"
#include "scene.h"
#include "scene_transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace raylab;

namespace {

Scene eyeCellScene(const char* name) {
    return loadScene(projectRoot() / "assets/scenes" / (std::string(name) + ".json"));
}

// Does the ray from O along unit D (t >= 0) come within R of C? (A little
// more than the GLSL's test finds: a stricter check of the lists.)
bool rayMeetsSphere(glm::dvec3 o, glm::dvec3 d, glm::dvec3 c, double r) {
    const double t = std::max(glm::dot(c - o, d), 0.0);
    return glm::length(o + t * d - c) <= r * (1.0 + 1e-6);
}

struct EyeCellAudit {
    long hits = 0;     // (ray, sphere) pairs where the ray meets the sphere
    long missing = 0;  // ... and the ray's cell does not list it
};

// Rays from CELLS' eye: half in any direction, half toward a sphere (its
// centre, moved by up to its radius), with the spheres anywhere on their swing.
EyeCellAudit auditEyeCells(const Scene& scene, const EyeCells& cells, int lookupResolution,
                           unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto randomDirection = [&] {
        glm::dvec3 v;
        do v = {unit(rng), unit(rng), unit(rng)};
        while (glm::length(v) > 1.0 || glm::length(v) < 1e-3);
        return glm::normalize(v);
    };
    EyeCellAudit a;
    const glm::dvec3 eye(cells.eye);
    for (int sample = 0; sample < 20000; ++sample) {
        glm::dvec3 toward = randomDirection();
        if (sample % 2 == 0) {
            const Sphere& s = scene.spheres[std::size_t(sample / 2) % scene.spheres.size()];
            toward = glm::dvec3(s.center) + 1.2 * double(s.radius) * randomDirection() - eye;
        }
        if (glm::length(toward) <= 0.0) continue;
        const glm::vec3 dir = glm::normalize(glm::vec3(toward));  // float, as the GLSL has it
        const glm::ivec2 list = cells.cells.at(std::size_t(cubeCell(lookupResolution, dir)));
        const auto first = cells.items.begin() + list.x, end = first + list.y;
        const double time = 10.0 * (0.5 + 0.5 * unit(rng));
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            const Sphere& s = scene.spheres[i];
            const glm::dvec3 centre = glm::dvec3(s.center + s.motion.offsetAt(float(time)));
            if (!rayMeetsSphere(eye, glm::dvec3(dir), centre, s.radius)) continue;
            ++a.hits;
            if (std::find(first, end, int(i)) == end) ++a.missing;
        }
    }
    return a;
}

void expectConservative(const std::string& name, const Scene& scene, glm::vec3 eye) {
    const EyeCells cells = buildEyeCells(scene, eye);
    const EyeCellAudit a = auditEyeCells(scene, cells, cells.resolution, 1);
    std::printf("[ figure ] %s: 6 faces x %d^2 cells; a list that is not empty holds %.2f spheres "
                "on average, %d at most (of %zu); %ld ray-sphere hits, %ld missing from their "
                "cell\n",
                name.c_str(), cells.resolution, cells.meanList(), cells.longestList(),
                scene.spheres.size(), a.hits, a.missing);
    EXPECT_GT(a.hits, 1000) << "too few hits to say anything";
    EXPECT_EQ(a.missing, 0) << "a ray's cell lacks a sphere the ray meets";
}

}  // namespace

TEST(EyeCells, EverySphereARayMeetsIsInItsCell) {
    for (const char* name : {"pro", "lite"}) {
        const Scene scene = eyeCellScene(name);
        expectConservative(std::string(name) + " from its camera", scene,
                           glm::vec3(scene.camera.position));
    }
    // An eye among the spheres, and one inside a sphere (every cell lists it).
    const Scene eyeCellsPro = eyeCellScene("pro");
    expectConservative("pro from a sphere's side", eyeCellsPro,
                       glm::vec3(eyeCellsPro.spheres[3].center +
                                 glm::dvec3(0.0, 0.0, 1.5 * eyeCellsPro.spheres[3].radius)));
    expectConservative("pro from inside a sphere", eyeCellsPro,
                       glm::vec3(eyeCellsPro.spheres[0].center));
}

// The margins are shares of the scene's size and of the eye's distance from
// the origin, so they hold for a scene resized or moved far away.
TEST(EyeCells, EverySphereARayMeetsIsInItsCellAtAnyScaleAndPlace) {
    const Scene eyeCellsPro = eyeCellScene("pro");
    for (double scale : {1e-4, 1e6}) {
        SceneTransform t;
        t.scale = scale;
        const Scene scaled = transformScene(eyeCellsPro, t);
        expectConservative("pro x " + std::to_string(scale), scaled,
                           glm::vec3(scaled.camera.position));
    }
    SceneTransform far;
    far.offset = glm::dvec3(1e5, 0.0, 0.0);
    const Scene moved = transformScene(eyeCellsPro, far);
    expectConservative("pro moved by 1e5", moved, glm::vec3(moved.camera.position));
}

// The audit can fail: lists built for spheres 10% smaller, around an eye
// one unit away (cells not rebuilt after the camera moved), or looked up on
// the wrong grid, miss spheres.
TEST(EyeCells, WrongCellsAreCaught) {
    const Scene eyeCellsPro = eyeCellScene("pro");
    const glm::vec3 eye(eyeCellsPro.camera.position);
    Scene smaller = eyeCellsPro;
    for (Sphere& s : smaller.spheres) s.radius *= 0.9;
    EyeCells shrunk = buildEyeCells(smaller, eye);
    const EyeCellAudit a = auditEyeCells(eyeCellsPro, shrunk, kEyeCellResolution, 2);
    std::printf("[ figure ] lists of spheres 10%% smaller: %ld of %ld hits missing\n", a.missing,
                a.hits);
    EXPECT_GT(a.missing, 0);
    EyeCells stale = buildEyeCells(eyeCellsPro, eye + glm::vec3(1.0f, 0.0f, 0.0f));
    stale.eye = eye;  // looked up for rays from the camera's new place
    const EyeCellAudit b = auditEyeCells(eyeCellsPro, stale, kEyeCellResolution, 3);
    std::printf("[ figure ] lists built one unit from the eye: %ld of %ld hits missing\n",
                b.missing, b.hits);
    EXPECT_GT(b.missing, 0);
    const EyeCellAudit c =
        auditEyeCells(eyeCellsPro, buildEyeCells(eyeCellsPro, eye), kEyeCellResolution / 2, 4);
    std::printf("[ figure ] lists looked up on a grid half as fine: %ld of %ld hits missing\n",
                c.missing, c.hits);
    EXPECT_GT(c.missing, 0);
}

TEST(EyeCells, OnlyForScenesTheySuit) {
    EXPECT_TRUE(eyeCellsSuit(eyeCellScene("pro")));
    EXPECT_FALSE(eyeCellsSuit(eyeCellScene("mesh"))) << "mesh triangles stay in the BVH";
    Scene none = eyeCellScene("lite");
    none.spheres.clear();
    EXPECT_FALSE(eyeCellsSuit(none));
}
