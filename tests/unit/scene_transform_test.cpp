// transformScene moves every length and position, and nothing else;
// sceneFrame leaves RayLab's own scenes exactly as they are (their shaders,
// baked preludes and reference pictures stay the same) and brings a resized
// or far-away copy back to a standard size near the origin.
#include "paths.h"
#include "scene_transform.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;

namespace {

Scene lite() { return loadScene(projectRoot() / "assets/scenes/lite.json"); }
Scene pro() { return loadScene(projectRoot() / "assets/scenes/pro.json"); }

}  // namespace

TEST(SceneTransform, MovesEveryLengthAndPosition) {
    const Scene a = pro();
    const SceneTransform t{4.0, glm::dvec3(8.0, -16.0, 32.0)};  // exact in float
    const Scene b = transformScene(a, t);
    auto moved = [&](glm::vec3 p) { return p * 4.0f + glm::vec3(8.0f, -16.0f, 32.0f); };
    EXPECT_EQ(b.camera.position, moved(a.camera.position));
    EXPECT_EQ(b.camera.yawDeg, a.camera.yawDeg);
    EXPECT_EQ(b.lights[1].position, moved(a.lights[1].position));
    EXPECT_EQ(b.spheres[2].center, moved(a.spheres[2].center));
    EXPECT_EQ(b.spheres[2].radius, 4.0f * a.spheres[2].radius);
    EXPECT_EQ(b.spheres[2].motion.amplitude, 4.0f * a.spheres[2].motion.amplitude);
    EXPECT_EQ(b.spheres[2].motion.axis, a.spheres[2].motion.axis);
    EXPECT_EQ(b.discs[0].center, moved(a.discs[0].center));
    EXPECT_EQ(b.discs[0].radius, 4.0f * a.discs[0].radius);
    EXPECT_EQ(b.discs[0].normal, a.discs[0].normal);
    EXPECT_EQ(b.triangles[5].vertices[2], moved(a.triangles[5].vertices[2]));
    ASSERT_FALSE(a.tori.empty());
    EXPECT_EQ(b.tori[0].center, moved(a.tori[0].center));
    EXPECT_EQ(b.tori[0].majorRadius, 4.0f * a.tori[0].majorRadius);
    EXPECT_EQ(b.tori[0].minorRadius, 4.0f * a.tori[0].minorRadius);
    EXPECT_EQ(b.glow.size, a.glow.size);  // in sphere radii
    EXPECT_EQ(b.fovYDeg, a.fovYDeg);
}

TEST(SceneTransform, MovesMeshCornersAndKeepsTheirNormals) {
    const Scene a = loadScene(projectRoot() / "assets/scenes/mesh.json");
    ASSERT_FALSE(a.meshes.empty());
    const Scene b = transformScene(a, SceneTransform{4.0, glm::dvec3(8.0, -16.0, 32.0)});
    const Mesh& m = a.meshes.back().mesh;
    const Mesh& n = b.meshes.back().mesh;
    ASSERT_EQ(n.positions.size(), m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); i += 97) {
        EXPECT_EQ(n.positions[i], m.positions[i] * 4.0f + glm::vec3(8.0f, -16.0f, 32.0f));
        EXPECT_EQ(n.normals[i], m.normals[i]);
    }
}

TEST(SceneTransform, PlanesKeepTheirTextureMapping) {
    Scene a;
    a.planes.push_back(Plane{{1.0f, 2.0f, 3.0f}, {0.0f, 1.0f, 0.0f}, 2.0f, 0});
    const Scene b = transformScene(a, SceneTransform{0.5, glm::dvec3(1.0, 0.0, 0.0)});
    EXPECT_EQ(b.planes[0].point, glm::vec3(1.5f, 1.0f, 1.5f));
    EXPECT_EQ(b.planes[0].tileSize, 1.0f);
}

TEST(SceneFrame, LeavesEveryShippedSceneAsItIs) {
    for (const auto& entry : fs::directory_iterator(projectRoot() / "assets" / "scenes"))
        if (entry.path().extension() == ".json") {
            EXPECT_TRUE(sceneFrame(loadScene(entry.path())).identity()) << entry.path();
        }
}

TEST(SceneFrame, BringsResizedAndMovedScenesBack) {
    for (double scale : {1e-4, 1e-3, 1e4, 1e6}) {
        const Scene moved = transformScene(lite(), SceneTransform{scale, glm::dvec3(0.0)});
        const SceneTransform f = sceneFrame(moved);
        // A power of two (exact), undoing the factor up to the band.
        EXPECT_EQ(std::exp2(std::round(std::log2(f.scale))), f.scale) << scale;
        const Scene back = transformScene(moved, f);
        EXPECT_TRUE(sceneFrame(back).identity()) << scale << ": a framed scene stays";
        // Lite is 86 units across; framed, 2 to 1024: its earth (radius
        // 1.3) between 1.3 * 2 / 86 and 1.3 * 1024 / 86.
        const double radius = back.spheres[1].radius;
        EXPECT_GE(radius, 1.3 * 2.0 / 86.5) << scale;
        EXPECT_LE(radius, 1.3 * 1024.0 / 86.5) << scale;
    }
    // Far away: moved by a multiple of a power of two, near the origin.
    const Scene far = transformScene(lite(), SceneTransform{1.0, glm::dvec3(1e5, -1e5, 1e5)});
    const SceneTransform f = sceneFrame(far);
    EXPECT_EQ(f.scale, 1.0);
    const glm::vec3 eye = f.point(far.camera.position);
    EXPECT_LT(glm::length(eye), 300.0f);
    // Exact: a float minus a nearby multiple of a power of two loses nothing.
    EXPECT_EQ(double(eye.x), double(far.camera.position.x) + f.offset.x);
}
