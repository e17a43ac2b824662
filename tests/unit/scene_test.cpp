// Scene files: a good one loads, every kind of bad one is a one-line error
// naming the file and the place.
#include "error.h"
#include "paths.h"
#include "scene.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

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
}  // namespace

TEST(Scene, LoadsAGoodFile) {
    ScratchDir dir;
    writeFile(dir / "scene.json", kGood);
    Scene s = loadScene(dir / "scene.json");
    ASSERT_EQ(s.spheres.size(), 2u);
    EXPECT_DOUBLE_EQ(s.spheres[1].radius, 0.5);
    EXPECT_FLOAT_EQ(s.fovYDeg, 50.0f);
    EXPECT_FLOAT_EQ(s.camera.yawDeg, 10.0f);
    EXPECT_NEAR(s.spheres[1].motion.offsetAt(1.0f).y, 2.0f,
                1e-5f);  // a quarter period: full amplitude
}

// Positions and lengths are read in double: a scene 1e6 from the origin
// keeps its centimetres (1000000.35 is 1000000.375 as a float), and so does
// a camera given there.
TEST(Scene, PositionsAndLengthsKeepEveryDigitOfTheFile) {
    ScratchDir dir;
    std::string text = replaced("\"center\": [2, 1, 0], \"radius\": 0.5",
                                "\"center\": [1000000.35, -999999.7, 0.1], \"radius\": 1e-7");
    const std::string eye = "\"position\": [0, 1, 5]";
    text.replace(text.find(eye), eye.size(), "\"position\": [1000000.35, 1, 1000005.1]");
    writeFile(dir / "scene.json", text);
    const Scene s = loadScene(dir / "scene.json");
    EXPECT_EQ(s.spheres[1].center, glm::dvec3(1000000.35, -999999.7, 0.1));
    EXPECT_EQ(s.spheres[1].radius, 1e-7);
    EXPECT_EQ(s.camera.position, glm::dvec3(1000000.35, 1.0, 1000005.1));
    EXPECT_NE(double(float(1000000.35)), 1000000.35) << "the case needs a number no float holds";
}

TEST(Scene, TheShippedScenesLoad) {
    for (const auto& entry : fs::directory_iterator(projectRoot() / "assets" / "scenes"))
        if (entry.path().extension() == ".json") {
            EXPECT_NO_THROW(loadScene(entry.path())) << entry.path();
        }
}

TEST(Scene, BadFilesGiveOneLineErrorsThatSayWhere) {
    EXPECT_NE(errorFor("{ \"background\": [0, 0, 0],\n  oops }")
                  .find("scene.json: line 2, column 3: JSON syntax error"),
              std::string::npos);
    EXPECT_NE(errorFor(replaced("\"radius\": 0.5", "\"radius\": -0.5"))
                  .find("spheres[1].radius: expected a positive number"),
              std::string::npos);
    EXPECT_NE(errorFor(replaced("\"color\": [1, 0, 0]", "\"color\": [1, 0]"))
                  .find("spheres[0].color: expected [x, y, z]"),
              std::string::npos);
    EXPECT_NE(errorFor(replaced("\"color\": [1, 0, 0]", "\"color\": [3, 0, 0]"))
                  .find("spheres[0].color: colour components"),
              std::string::npos);
    EXPECT_NE(errorFor(replaced("\"yaw\": 10,", "")).find("camera: missing \"yaw\""),
              std::string::npos);
    EXPECT_NE(errorFor(replaced("\"center\": [0, 1, 0]", "\"center\": [0, \"1\", 0]"))
                  .find("spheres[0].center[1]: expected a number"),
              std::string::npos);
    EXPECT_NE(errorFor(replaced("\"period\": 4", "\"period\": 0")).find("spheres[1].motion.period"),
              std::string::npos);
    EXPECT_NE(errorFor("[]").find("expected an object"), std::string::npos);
}

// Found by tests/fuzz/fuzz_scene: the JSON library throws out_of_range, not
// parse_error, for a number beyond a double; it must still be an Error.
TEST(Scene, HugeNumberIsAnErrorNotACrash) {
    EXPECT_NE(errorFor(replaced("\"yaw\": 10", "\"yaw\": 1e500"))
                  .find("scene.json: JSON number out of range"),
              std::string::npos);
    EXPECT_NE(errorFor("[-1e99999]").find("JSON number out of range"), std::string::npos);
}

TEST(Scene, MaterialsAreATableAndSpheresNameTheirEntry) {
    ScratchDir dir;
    writeFile(dir / "scene.json", R"({
      "background": [0, 0, 0],
      "camera": {"position": [0, 0, 5], "yaw": 0, "pitch": 0},
      "materials": {
        "shiny": {"ambient": [0.1, 0, 0], "diffuse": [0.8, 0, 0], "specular": [1, 1, 1], "shininess": 80},
        "matte": {"ambient": [0, 0.1, 0], "diffuse": [0, 0.8, 0], "specular": [0, 0, 0], "shininess": 1}
      },
      "lights": [{"position": [1, 2, 3], "color": [1, 1, 1]}, {"position": [-1, 2, 3], "color": [0.5, 0.5, 0.5]}],
      "spheres": [
        {"center": [0, 0, 0], "radius": 1, "material": "matte"},
        {"center": [2, 0, 0], "radius": 1, "material": "shiny"},
        {"center": [4, 0, 0], "radius": 1, "color": [0, 0, 1]}
      ]})");
    Scene s = loadScene(dir / "scene.json");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FLOAT_EQ(s.lights[1].color.r, 0.5f);
    ASSERT_EQ(s.materials.size(), 3u)
        << "two named materials plus one for the flat-coloured sphere";
    EXPECT_EQ(s.materials[std::size_t(s.spheres[0].material)].name, "matte");
    EXPECT_EQ(s.materials[std::size_t(s.spheres[1].material)].name, "shiny");
    EXPECT_FLOAT_EQ(s.materials[std::size_t(s.spheres[1].material)].shininess, 80.0f);
    EXPECT_FLOAT_EQ(s.materials[std::size_t(s.spheres[2].material)].diffuse.b, 1.0f)
        << "a flat colour is a diffuse colour";
}

TEST(Scene, UnknownOrMalformedMaterialsAreErrors) {
    const std::string base =
        R"({"background": [0, 0, 0], "camera": {"position": [0, 0, 5], "yaw": 0, "pitch": 0},
      "materials": {"m": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 30}},
      "spheres": [{"center": [0, 0, 0], "radius": 1, "material": "m"}]})";
    auto with = [&](const std::string& from, const std::string& to) {
        std::string t = base;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    EXPECT_NE(errorFor(with("\"material\": \"m\"", "\"material\": \"gold\""))
                  .find("spheres[0].material: unknown material \"gold\""),
              std::string::npos);
    EXPECT_NE(errorFor(with("\"material\": \"m\"", "\"material\": 3"))
                  .find("spheres[0].material: expected the name"),
              std::string::npos);
    EXPECT_NE(errorFor(with("\"shininess\": 30", "\"shininess\": 0"))
                  .find("materials.m.shininess: expected a positive number"),
              std::string::npos);
    EXPECT_NE(
        errorFor(with("\"specular\": [0, 0, 0], ", "")).find("materials.m: missing \"specular\""),
        std::string::npos);
    EXPECT_NE(errorFor(with("\"spheres\"", "\"lights\": [{\"position\": [0, 0]}], \"spheres\""))
                  .find("lights[0].position: expected [x, y, z]"),
              std::string::npos);
}

TEST(Scene, MaterialTypesForReflectionAndRefraction) {
    ScratchDir dir;
    writeFile(dir / "scene.json",
              R"({"background": [0, 0, 0], "camera": {"position": [0, 0, 5], "yaw": 0, "pitch": 0},
      "materials": {
        "glass": {"type": "glass", "ior": 1.5, "ambient": [0, 0, 0], "diffuse": [0, 0, 0], "specular": [1, 1, 1], "shininess": 100},
        "gold": {"type": "metal", "n": [0.143, 0.375, 1.442], "k": [3.983, 2.386, 1.603], "ambient": [0, 0, 0], "diffuse": [0, 0, 0], "specular": [1, 1, 1], "shininess": 50},
        "plain": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1}
      },
      "spheres": []})");
    Scene s = loadScene(dir / "scene.json");
    ASSERT_EQ(s.materials.size(), 3u);
    auto byName = [&](const std::string& n) {
        return *std::find_if(s.materials.begin(), s.materials.end(),
                             [&](const Material& m) { return m.name == n; });
    };
    EXPECT_EQ(byName("glass").type, Material::Type::Glass);
    EXPECT_FLOAT_EQ(byName("glass").ior, 1.5f);
    EXPECT_EQ(byName("gold").type, Material::Type::Metal);
    EXPECT_FLOAT_EQ(byName("gold").k.r, 3.983f);
    EXPECT_EQ(byName("plain").type, Material::Type::Plastic) << "plastic is the default";

    const std::string bad =
        R"({"background": [0, 0, 0], "camera": {"position": [0, 0, 5], "yaw": 0, "pitch": 0},
      "materials": {"m": {"type": "TYPE", "ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 30 EXTRA}},
      "spheres": []})";
    auto with = [&](const std::string& type, const std::string& extra) {
        std::string t = bad;
        t.replace(t.find("TYPE"), 4, type);
        t.replace(t.find("EXTRA"), 5, extra);
        return t;
    };
    EXPECT_NE(errorFor(with("wood", "")).find("materials.m.type: unknown type \"wood\""),
              std::string::npos);
    EXPECT_NE(errorFor(with("glass", "")).find("materials.m: missing \"ior\""), std::string::npos);
    EXPECT_NE(
        errorFor(with("glass", ", \"ior\": 0.5")).find("index of refraction must lie in [1, 4]"),
        std::string::npos);
    EXPECT_NE(errorFor(with("metal", ", \"n\": [1, 1, 1]")).find("materials.m: missing \"k\""),
              std::string::npos);
}

TEST(Scene, MissingFileIsAnError) { EXPECT_THROW(loadScene("/nonexistent/scene.json"), Error); }
