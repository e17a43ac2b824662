// Tori hidden from the lights (framework/src/raytrace/scene/hidden_tori.h):
// pro's torus sits in its closed glass cube with every light outside, so
// the light buffer's shadow rays may leave it out; any scene where that is
// not so - an open shell, a dented one, a torus or a light outside it - must
// keep it. The pictures (the same bytes as the walk, and torus shadows where
// the cube is gone) are checked in tests/e2e/bvh_images_test.cpp.
#include "hidden_tori.h"
#include "paths.h"
#include "scene.h"
#include "scene_transform.h"

#include <gtest/gtest.h>

#include <vector>

using namespace raylab;

namespace {

Scene pro() { return loadScene(projectRoot() / "assets/scenes/pro.json"); }

// The glass cube's triangles: the ones around the torus (pro's cube is
// 1.8 wide, centred on the torus; its mirror is farther away).
std::vector<std::size_t> cubeTriangles(const Scene& scene) {
    std::vector<std::size_t> cube;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        bool near = true;
        for (const glm::dvec3& v : scene.triangles[i].vertices)
            near = near && glm::length(v - scene.tori[0].center) < 1.6;
        if (near) cube.push_back(i);
    }
    return cube;
}

}  // namespace

TEST(HiddenTori, ProsTorusIsHiddenInItsCube) {
    EXPECT_TRUE(toriHiddenFromLights(pro()));
    SceneTransform far;
    far.offset = glm::dvec3(1e5, 0.0, 0.0);
    far.scale = 1e3;
    EXPECT_TRUE(toriHiddenFromLights(transformScene(pro(), far))) << "at another scale and place";
}

// Each way the reasoning can fail is seen.
TEST(HiddenTori, AnyGapKeepsTheTorus) {
    Scene open = pro();
    const std::vector<std::size_t> cube = cubeTriangles(open);
    ASSERT_EQ(cube.size(), 12u) << "pro's cube: 12 triangles";
    open.triangles.erase(open.triangles.begin() + std::ptrdiff_t(cube[5]));  // a face half open
    EXPECT_FALSE(toriHiddenFromLights(open)) << "an open shell";

    Scene dented = pro();
    const glm::dvec3 centre = dented.tori[0].center;  // the cube's centre too
    const glm::dvec3 corner = dented.triangles[cube[0]].vertices[0];
    for (Triangle& t : dented.triangles)  // one corner pushed halfway in, everywhere it is shared
        for (glm::dvec3& v : t.vertices)
            if (v == corner) v = 0.5 * (v + centre);
    EXPECT_FALSE(toriHiddenFromLights(dented)) << "a shell that is not convex";

    Scene torusOut = pro();
    torusOut.tori[0].center.y += 10.0;
    EXPECT_FALSE(toriHiddenFromLights(torusOut)) << "the torus outside the cube";

    Scene torusLarge = pro();
    torusLarge.tori[0].majorRadius *= 3.0;
    EXPECT_FALSE(toriHiddenFromLights(torusLarge)) << "a torus through the cube's faces";

    Scene lightIn = pro();
    lightIn.lights[1].position = lightIn.tori[0].center + glm::dvec3(0.0, 0.7, 0.0);
    EXPECT_FALSE(toriHiddenFromLights(lightIn)) << "a light inside the cube";

    Scene none = pro();
    none.tori.clear();
    EXPECT_FALSE(toriHiddenFromLights(none)) << "no tori: nothing to leave out";
}
