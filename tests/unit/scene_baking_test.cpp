// A scene compiled into the shader (framework/src/raytrace/scene/scene_baking.h): every
// static value appears as a constant that reads back as the same float, and
// the arrays are sized to the scene. (That the baked shader draws the same
// pictures: tests/e2e/bvh_images_test.cpp.)
#include "paths.h"
#include "scene.h"
#include "scene_baking.h"

#include <gtest/gtest.h>

#include <regex>

using namespace raylab;

namespace {
Scene pro() { return loadScene(projectRoot() / "assets/scenes/pro.json"); }
}  // namespace

TEST(SceneBaking, CountsAndArraySizesAreTheScenes) {
    Scene s = pro();
    std::string g = bakedSceneGlsl(s);
    EXPECT_NE(g.find("const int uSphereCount = " + std::to_string(s.spheres.size()) + ";"),
              std::string::npos)
        << g.substr(0, 400);
    EXPECT_NE(g.find("const int uTriangleCount = " + std::to_string(s.triangles.size()) + ";"),
              std::string::npos);
    EXPECT_NE(g.find("const int uPlaneCount = 0;"), std::string::npos) << "pro has no planes";
    EXPECT_NE(g.find("uMatAmbient[" + std::to_string(s.materials.size()) + "]"), std::string::npos);
    // A kind the scene lacks still gets a one-element array: GLSL has no empty ones.
    EXPECT_NE(g.find("const vec4 uPlanes[1] = vec4[1](vec4(0.0));"), std::string::npos);
    std::vector<std::string> d = bakedSceneDefines(s);
    EXPECT_NE(std::find(d.begin(), d.end(), "MAX_SPHERES " + std::to_string(s.spheres.size())),
              d.end());
    EXPECT_NE(std::find(d.begin(), d.end(), "MAX_PLANES 1"), d.end());
    EXPECT_NE(std::find(d.begin(), d.end(), "SCENE_BAKED"), d.end());
}

TEST(SceneBaking, EveryFloatLiteralReadsBackExactly) {
    Scene s = pro();
    s.lights.at(0).position = {0.1f, 1.0f / 3.0f, 12345.678f};
    std::string g = bakedSceneGlsl(s);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(
        g, m,
        std::regex(R"(uLightPositions\[\d+\] = vec3\[\d+\]\(vec3\(([^,]+), ([^,]+), ([^)]+)\))")));
    for (int c = 0; c < 3; ++c) {
        std::string text = m[c + 1].str();
        EXPECT_NE(text.find_first_of(".e"), std::string::npos)
            << text << " would be an int in GLSL";
        EXPECT_EQ(std::stof(text), s.lights[0].position[c]) << text;
    }
    // Whole numbers become float literals too.
    EXPECT_EQ(g.find("vec3(1, "), std::string::npos);
}
