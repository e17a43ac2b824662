// Stage 01 (ray casting), end to end through the `raylab` binary:
//  - the solution matches the committed reference images from every view;
//  - the same check fails on the untouched lab and on each known mistake;
//  - the C++ camera and the GPU agree on the ray through a pixel.
// Metric and tolerance: see tests/README.md ("How images are compared").
#include "camera.h"
#include "image.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

using namespace raylab::test;

namespace {
const std::string kReferences = quote((sourceDir() / "tests/reference/01-raycast").string());
}

TEST(Stage01, SolutionMatchesTheCommittedReferenceImages) {
    CommandResult r = runRaylab("check --stage 01 --solution --against " + kReferences);
    EXPECT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("6 passed, 0 failed"), std::string::npos) << r.all();
}

TEST(Stage01, SolutionMatchesTheSolutionRenderedLive) {
    CommandResult r = runRaylab("check --stage 01 --solution");
    EXPECT_EQ(r.exitCode, 0) << r.all();
}

TEST(Stage01, UntouchedLabFailsEveryViewAndNamesItsTodos) {
    CommandResult r = runRaylab("check --stage 01 --lab");
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_EQ(failedViews(r.out).size(), 6u) << r.all();
    EXPECT_NE(r.err.find("labs/01-raycast/intersect_sphere.glsl:13: TODO(01.a)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("labs/01-raycast/find_closest.glsl:10: TODO(01.b)"), std::string::npos) << r.err;
}

TEST(Stage01, SolvedLabCopyPasses) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    CommandResult r = runRaylab("check --stage 01 --lab " + quote(lab.path()));
    EXPECT_EQ(r.exitCode, 0) << r.all();
    EXPECT_EQ(r.err.find("open TODO"), std::string::npos) << "a solved lab has no open TODOs: " << r.err;
}

// Each file in tests/mistakes/01-raycast/ is a typical mistake, written as a
// text replacement in the solved lab. The check must fail on the views it names.
TEST(Stage01, EveryKnownMistakeIsCaught) {
    int mistakes = 0;
    for (const auto& entry : fs::directory_iterator(sourceDir() / "tests/mistakes/01-raycast")) {
        auto spec = nlohmann::json::parse(readFile(entry.path()));
        SCOPED_TRACE(entry.path().filename().string() + ": " + spec["mistake"].get<std::string>());
        ScratchDir lab;
        writeSolvedLabs(lab.path());
        for (const auto& pair : spec["replace"]) replaceInFile(lab / ("01-raycast/" + spec["file"].get<std::string>()), pair[0], pair[1]);
        CommandResult r = runRaylab("check --stage 01 --lab " + quote(lab.path()));
        EXPECT_EQ(r.exitCode, 1) << r.all();
        std::vector<std::string> failed = failedViews(r.out);
        for (const auto& view : spec["caught_by"])
            EXPECT_NE(std::find(failed.begin(), failed.end(), view.get<std::string>()), failed.end())
                << "expected view " << view << " to fail\n" << r.out;
        ++mistakes;
    }
    EXPECT_GE(mistakes, 3);
}

// A tiny sphere placed on the C++ camera's ray through one pixel must show up
// in exactly that pixel of the GPU image.
TEST(Stage01, GpuPrimaryRaysMatchTheCameraMaths) {
    ScratchDir dir;
    const int w = 64, h = 48;
    const glm::vec3 eye(0.5f, 1.0f, 4.0f);
    raylab::Camera cam(raylab::CameraPose{eye, 20.0f, -7.0f}, 40.0f);
    const int px = 13, py = 37;
    glm::vec3 center = eye + 30.0f * glm::normalize(cam.rayDirection(px, py, w, h));
    writeFile(dir / "dot.json", "{\"background\": [0, 0, 0], \"camera\": {\"position\": [0.5, 1, 4], \"yaw\": 20, \"pitch\": -7, \"fov_y\": 40},"
                                "\"spheres\": [{\"center\": [" + std::to_string(center.x) + "," + std::to_string(center.y) + "," +
                                    std::to_string(center.z) + "], \"radius\": 0.05, \"color\": [1, 1, 1]}]}");
    CommandResult r = runRaylab("render --stage 01 --solution --size 64x48 --scene " + quote(dir / "dot.json") + " --out " + quote(dir / "dot.png"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    raylab::Image img = raylab::loadPng(dir / "dot.png");
    int lit = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (img.pixel(x, y)[0] > 128) {
                ++lit;
                EXPECT_TRUE(std::abs(x - px) <= 0 && std::abs(y - py) <= 0) << "white pixel at (" << x << ", " << y << "), expected only (" << px << ", " << py << ")";
            }
    EXPECT_EQ(lit, 1);
}
