// transformScene moves every length and position, and nothing else;
// sceneFrame leaves RayLab's own scenes exactly as they are (their shaders,
// baked preludes and reference pictures stay the same) and brings a resized
// copy back to a standard size, a far-away one to its eye.
#include "paths.h"
#include "scene_transform.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;

namespace {

Scene lite() { return loadScene(projectRoot() / "assets/scenes/lite.json"); }
Scene transformPro() { return loadScene(projectRoot() / "assets/scenes/pro.json"); }

}  // namespace

TEST(SceneTransform, MovesEveryLengthAndPosition) {
    const Scene a = transformPro();
    const SceneTransform t{4.0, glm::dvec3(8.0, -16.0, 32.0)};  // exact
    const Scene b = transformScene(a, t);
    auto moved = [&](const glm::dvec3& p) { return p * 4.0 + glm::dvec3(8.0, -16.0, 32.0); };
    EXPECT_EQ(b.camera.position, moved(a.camera.position));
    EXPECT_EQ(b.camera.yawDeg, a.camera.yawDeg);
    EXPECT_EQ(b.lights[1].position, moved(a.lights[1].position));
    EXPECT_EQ(b.spheres[2].center, moved(a.spheres[2].center));
    EXPECT_EQ(b.spheres[2].radius, 4.0 * a.spheres[2].radius);
    EXPECT_EQ(b.spheres[2].motion.amplitude, 4.0 * a.spheres[2].motion.amplitude);
    EXPECT_EQ(b.spheres[2].motion.axis, a.spheres[2].motion.axis);
    EXPECT_EQ(b.discs[0].center, moved(a.discs[0].center));
    EXPECT_EQ(b.discs[0].radius, 4.0 * a.discs[0].radius);
    EXPECT_EQ(b.discs[0].normal, a.discs[0].normal);
    EXPECT_EQ(b.triangles[5].vertices[2], moved(a.triangles[5].vertices[2]));
    ASSERT_FALSE(a.tori.empty());
    EXPECT_EQ(b.tori[0].center, moved(a.tori[0].center));
    EXPECT_EQ(b.tori[0].majorRadius, 4.0 * a.tori[0].majorRadius);
    EXPECT_EQ(b.tori[0].minorRadius, 4.0 * a.tori[0].minorRadius);
    EXPECT_EQ(b.glow.size, a.glow.size);  // in sphere radii
    EXPECT_EQ(b.fovYDeg, a.fovYDeg);
}

TEST(SceneTransform, MovesMeshCornersAndKeepsTheirNormals) {
    const Scene a = loadScene(projectRoot() / "assets/scenes/mesh.json");
    ASSERT_FALSE(a.meshes.empty());
    const Scene b = transformScene(a, SceneTransform{4.0, glm::dvec3(8.0, -16.0, 32.0)});
    const MeshObject& m = a.meshes.back();
    const MeshObject& n = b.meshes.back();
    ASSERT_EQ(n.positions.size(), m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); i += 97) {
        EXPECT_EQ(n.positions[i], m.positions[i] * 4.0 + glm::dvec3(8.0, -16.0, 32.0));
        EXPECT_EQ(n.normals[i], m.normals[i]);
    }
}

TEST(SceneTransform, PlanesKeepTheirTextureMapping) {
    Scene a;
    a.planes.push_back(Plane{{1.0, 2.0, 3.0}, {0.0f, 1.0f, 0.0f}, 2.0, 0});
    const Scene b = transformScene(a, SceneTransform{0.5, glm::dvec3(1.0, 0.0, 0.0)});
    EXPECT_EQ(b.planes[0].point, glm::dvec3(1.5, 1.0, 1.5));
    EXPECT_EQ(b.planes[0].tileSize, 1.0);
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
}

// Far away, with fractional offsets: the eye becomes the origin (to within
// a 1024th of the scene's size), and every position keeps its small digits,
// because the scene is held and moved in double. A scene read into floats
// would have lost them (1e6 + 0.35 is 1e6 + 0.375 in float).
TEST(SceneFrame, MovesAFarSceneToItsEyeKeepingItsDigits) {
    const Scene base = lite();
    for (const glm::dvec3 offset : {glm::dvec3(1e5 + 0.35, -1e5 - 0.123, 1e5 + 0.7),
                                    glm::dvec3(-1e6 - 0.35, 1e6 + 0.1, 0.3)}) {
        const Scene far = transformScene(base, SceneTransform{1.0, offset});
        const SceneTransform f = sceneFrame(far);
        EXPECT_EQ(f.scale, 1.0);
        const Scene framed = transformScene(far, f);
        EXPECT_LT(glm::length(framed.camera.position), 86.5 / 1024.0 * 2.0)
            << "the eye at the origin";
        EXPECT_TRUE(sceneFrame(framed).identity()) << "a framed scene stays";
        // The framed scene is the original moved by a whole number of steps:
        // its floats are the original's relative to the eye.
        const glm::dvec3 shift = offset + f.offset;
        for (std::size_t i = 0; i < base.spheres.size(); ++i)
            EXPECT_NEAR(glm::length(framed.spheres[i].center - (base.spheres[i].center + shift)),
                        0.0, 1e-9)
                << i;
        EXPECT_NEAR(glm::length(framed.camera.position - (base.camera.position + shift)), 0.0,
                    1e-9);
    }
}
