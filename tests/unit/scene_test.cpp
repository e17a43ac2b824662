// Scene files: a good one loads, every kind of bad one is a one-line error
// naming the file and the place.
#include "error.h"
#include "paths.h"
#include "scene.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab;
using raylab::test::ScratchDir;
using raylab::test::writeFile;

namespace {
const std::string kGood = R"({
  "background": [0.1, 0.2, 0.3],
  "camera": {"position": [0, 1, 5], "yaw": 10, "pitch": -5, "fov_y": 50},
  "spheres": [
    {"center": [0, 1, 0], "radius": 1, "color": [1, 0, 0]},
    {"center": [2, 1, 0], "radius": 0.5, "color": [0, 1, 0], "motion": {"axis": [0, 1, 0], "amplitude": 2, "period": 4}}
  ]
})";

std::string errorFor(const std::string& text) {
    ScratchDir dir;
    writeFile(dir / "scene.json", text);
    try {
        loadScene(dir / "scene.json");
    } catch (const Error& e) {
        std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "error must be one line: " << msg;
        return msg;
    }
    return "";
}

std::string replaced(const std::string& from, const std::string& to) {
    std::string s = kGood;
    s.replace(s.find(from), from.size(), to);
    return s;
}
} // namespace

TEST(Scene, LoadsAGoodFile) {
    ScratchDir dir;
    writeFile(dir / "scene.json", kGood);
    Scene s = loadScene(dir / "scene.json");
    ASSERT_EQ(s.spheres.size(), 2u);
    EXPECT_FLOAT_EQ(s.spheres[1].radius, 0.5f);
    EXPECT_FLOAT_EQ(s.fovYDeg, 50.0f);
    EXPECT_FLOAT_EQ(s.camera.yawDeg, 10.0f);
    EXPECT_NEAR(s.spheres[1].motion.offsetAt(1.0f).y, 2.0f, 1e-5f);  // a quarter period: full amplitude
}

TEST(Scene, TheShippedScenesLoad) {
    for (const auto& entry : fs::directory_iterator(projectRoot() / "assets" / "scenes"))
        EXPECT_NO_THROW(loadScene(entry.path())) << entry.path();
}

TEST(Scene, BadFilesGiveOneLineErrorsThatSayWhere) {
    EXPECT_NE(errorFor("{ \"background\": [0, 0, 0],\n  oops }").find("scene.json: line 2, column 3: JSON syntax error"), std::string::npos);
    EXPECT_NE(errorFor(replaced("\"radius\": 0.5", "\"radius\": -0.5")).find("spheres[1].radius: expected a positive number"), std::string::npos);
    EXPECT_NE(errorFor(replaced("\"color\": [1, 0, 0]", "\"color\": [1, 0]")).find("spheres[0].color: expected [x, y, z]"), std::string::npos);
    EXPECT_NE(errorFor(replaced("\"color\": [1, 0, 0]", "\"color\": [3, 0, 0]")).find("spheres[0].color: colour components"), std::string::npos);
    EXPECT_NE(errorFor(replaced("\"yaw\": 10,", "")).find("camera: missing \"yaw\""), std::string::npos);
    EXPECT_NE(errorFor(replaced("\"center\": [0, 1, 0]", "\"center\": [0, \"1\", 0]")).find("spheres[0].center[1]: expected a number"), std::string::npos);
    EXPECT_NE(errorFor(replaced("\"period\": 4", "\"period\": 0")).find("spheres[1].motion.period"), std::string::npos);
    EXPECT_NE(errorFor("[]").find("expected an object"), std::string::npos);
}

TEST(Scene, MissingFileIsAnError) {
    EXPECT_THROW(loadScene("/nonexistent/scene.json"), Error);
}
