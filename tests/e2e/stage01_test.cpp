// Stage 01 specifics (the checks every stage gets are in stage_checks_test.cpp):
//  - the untouched lab names each open TODO with file and line;
//  - raylab check --checks runs the checks it names;
//  - the C++ camera and the GPU agree on the ray through a pixel.
#include "camera.h"
#include "image.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

TEST(Stage01, UntouchedLabFailsEveryViewAndNamesItsTodosWithFileAndLine) {
    CommandResult r = runRaylab("check --stage 01 --lab");
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_EQ(failedViews(r.out).size(), 8u)
        << "six views, the intersectSphere and findClosest checks\n"
        << r.all();
    EXPECT_NE(r.err.find("labs/01-raycast/intersect_sphere.glsl:18: TODO(01.a)"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("labs/01-raycast/find_closest.glsl:10: TODO(01.b)"), std::string::npos)
        << r.err;
}

// --checks: only the checks it names run (a view, a function check), and a
// name the stage has no check of is a one-line error that lists its checks.
TEST(Stage01, ChecksOptionRunsOnlyTheNamedChecks) {
    CommandResult r =
        runRaylab("check --stage 01 --lab --size 80x60 --checks front,intersectSphere");
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_EQ(failedViews(r.out), (std::vector<std::string>{"intersectSphere", "front"}))
        << r.all();
    EXPECT_NE(r.out.find("0 passed, 2 failed"), std::string::npos) << r.out;
    CommandResult bad = runRaylab("check --stage 01 --solution --checks front,frnt");
    EXPECT_EQ(bad.exitCode, 2) << bad.all();
    EXPECT_NE(bad.err.find("--checks: stage 01-raycast has no check 'frnt' (its checks: front, "
                           "close-overlap, hidden, inside, among, moving, intersectSphere, "
                           "findClosest)"),
              std::string::npos)
        << bad.err;
}

TEST(Stage01, KnownMistakesCoverTheGuidesList) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(sourceDir() / "tests/mistakes/01-raycast"))
        count += entry.path().extension() == ".json";
    EXPECT_GE(count, 3) << "issue: far root, discriminant sign, no t > 0 check at least";
}

// A tiny sphere placed on the C++ camera's ray through one pixel must show up
// in exactly that pixel of the GPU image.
TEST(Stage01, GpuPrimaryRaysMatchTheCameraMaths) {
    ScratchDir dir;
    const int w = 64, h = 48;
    const glm::vec3 eye(0.5f, 1.0f, 4.0f);
    raylab::Camera cam(raylab::CameraPose{glm::dvec3(eye), 20.0f, -7.0f}, 40.0f);
    const int px = 13, py = 37;
    glm::vec3 center = eye + 30.0f * glm::normalize(cam.rayDirection(px, py, w, h));
    writeFile(dir / "dot.json", "{\"background\": [0, 0, 0], \"camera\": {\"position\": [0.5, 1, "
                                "4], \"yaw\": 20, \"pitch\": -7, \"fov_y\": 40},"
                                "\"spheres\": [{\"center\": [" +
                                    std::to_string(center.x) + "," + std::to_string(center.y) +
                                    "," + std::to_string(center.z) +
                                    "], \"radius\": 0.05, \"color\": [1, 1, 1]}]}");
    CommandResult r = runRaylab("render --stage 01 --solution --size 64x48 --scene " +
                                quote(dir / "dot.json") + " --out " + quote(dir / "dot.png"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    raylab::Image img = raylab::loadPng(dir / "dot.png");
    int lit = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (img.pixel(x, y)[0] > 128) {
                ++lit;
                EXPECT_TRUE(x == px && y == py) << "white pixel at (" << x << ", " << y
                                                << "), expected only (" << px << ", " << py << ")";
            }
    EXPECT_EQ(lit, 1);
}
