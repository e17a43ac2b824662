// `raylab demo` without a display: a fly-through of the lite or pro scene
// rendered to PNG files and timed; bad scenes fail before anything is written.
#include "image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <regex>

using namespace raylab::test;

namespace {

// Runs `raylab ARGS` with DIR as the working directory.
CommandResult demoIn(const ScratchDir& dir, const std::string& args) {
    return runCommand("cd " + quote(dir.path().string()) +
                      " && env -u DISPLAY -u WAYLAND_DISPLAY " + quote(raylabExe().string()) +
                      " demo " + args);
}

int entries(const fs::path& dir) {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

// A copy of the lite scene with one text replacement, in DIR.
fs::path liteWith(const ScratchDir& dir, const std::string& name, const std::string& from,
                  const std::string& to) {
    std::string text = readFile(sourceDir() / "assets/scenes/lite.json");
    text.replace(text.find(from), from.size(), to);
    // Texture paths are relative to the scene file's folder.
    for (std::size_t at; (at = text.find("\"../textures/")) != std::string::npos;)
        text.replace(at, 13, "\"" + (sourceDir() / "assets/textures").string() + "/");
    fs::create_directories(dir / "scenes");
    writeFile(dir / "scenes" / name, text);
    return dir / "scenes" / name;
}

}  // namespace

TEST(Demo, HeadlessFlyThroughWritesFramesToANewFolderAndPrintsTheMedian) {
    ScratchDir dir;
    CommandResult r = demoIn(dir, "--scene lite --frames 2 --size 160x120");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("scene assets/scenes/lite.json"), std::string::npos) << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex("frame time: median [0-9.]+ ms"))) << r.out;
    std::smatch folder;
    ASSERT_TRUE(std::regex_search(r.out, folder, std::regex("2 frames written to (\\S+)")))
        << r.out;
    fs::path out = folder[1].str();
    EXPECT_EQ(out.parent_path(), fs::canonical(dir.path()))
        << "the default folder is new, under the current directory";
    EXPECT_EQ(entries(out), 2);
    raylab::Image first = raylab::loadPng(out / "frame-000.png"),
                  second = raylab::loadPng(out / "frame-001.png");
    EXPECT_EQ(first.width, 160);
    EXPECT_EQ(first.height, 120);
    EXPECT_NE(first.rgba, second.rgba) << "the camera flies: frames differ";

    // A second run never reuses the first one's folder.
    CommandResult again = demoIn(dir, "--scene lite --frames 1 --size 160x120");
    ASSERT_EQ(again.exitCode, 0) << again.all();
    EXPECT_EQ(entries(dir.path()), 2);
}

TEST(Demo, ProSceneRendersIntoTheGivenFolderWithShadowsOff) {
    ScratchDir dir;
    CommandResult r =
        demoIn(dir, "--scene pro --frames 1 --size 160x120 --no-shadows --out frames");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("shadows off"), std::string::npos) << r.out;
    raylab::Image frame = raylab::loadPng(dir / "frames/frame-000.png");
    EXPECT_EQ(frame.width, 160);
}

TEST(Demo, BadScenesFailWithOneLineBeforeAnyFolderIsMade) {
    ScratchDir dir;
    const std::string lite = readFile(sourceDir() / "assets/scenes/lite.json");
    const std::string sunRadiusLine = std::to_string(
        1 + std::count(lite.begin(), lite.begin() + long(lite.find("\"radius\": 7.0")), '\n'));
    struct Case {
        std::string args, expected;
    } cases[] = {
        {"--scene nowhere.json", "scene file nowhere.json does not exist"},
        {"--scene " +
             quote(liteWith(dir, "syntax.json", "\"radius\": 7.0", "\"radius\": 7.0,,").string()),
         "syntax.json: line " + sunRadiusLine + ", column"},
        {"--scene " + quote(liteWith(dir, "texture.json", "moon.png", "mooon.png").string()),
         "materials.moon.texture: file"},
        {"--scene " +
             quote(liteWith(dir, "radius.json", "\"radius\": 7.0", "\"radius\": \"big\"").string()),
         "radius.json: spheres[0].radius: expected a number"},
        {"--scene lite --frames 0", "--frames must be between 1 and 1000"},
        {"--scene lite --depth 9", "--depth must be between 1 and 8"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        CommandResult r = demoIn(dir, c.args + " --size 160x120");
        EXPECT_EQ(r.exitCode, 2) << r.all();
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    }
    EXPECT_EQ(entries(dir.path()), 1)
        << "only the scenes/ folder of this test: no output folder was made";
}

TEST(Demo, ASceneWithMoreObjectsThanTheShaderSupportsIsRefused) {
    ScratchDir dir;
    std::string spheres;
    // lite's 10 and 99,991 more: one past stage 08's limit.
    for (int i = 0; i < 99991; ++i)
        spheres += R"({"center": [0, 0, 0], "radius": 1, "material": "red"},)";
    fs::path scene = liteWith(dir, "bad.json", "\"spheres\": [", "\"spheres\": [" + spheres);
    CommandResult r = demoIn(dir, "--scene " + quote(scene.string()) + " --size 160x120");
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(
        r.err.find("bad.json: spheres: 100001 spheres, but stage 08-full supports at most 100000"),
        std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
}

TEST(Demo, FurTrackDrawsBothTechniquesOnEachSceneAndTimesThem) {
    ScratchDir dir;
    CommandResult r = demoIn(dir, "--track fur --headless --frames 2 --size 80x60 --scene torus "
                                  "--out fur");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("torus"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fur shader"), std::string::npos) << r.out;
    const fs::path a = dir / "fur" / "torus-shells_and_fins-frame-001.png";
    const fs::path b = dir / "fur" / "torus-fur_shader-frame-001.png";
    ASSERT_TRUE(fs::exists(a) && fs::exists(b)) << r.all();
    EXPECT_NE(readFile(a), readFile(b)) << "the two techniques draw different pictures";
    EXPECT_EQ(entries(dir / "fur"), 4);
}

// --emulate-geometry draws the page's way (the geometry shaders rewritten
// into vertex shaders): the same pictures as the real geometry shaders'
// (tests/fur/geometry_emulation_draw_test.cpp compares them closely), and
// the ray tracer, which has none, refuses it.
TEST(Demo, FurTrackEmulatesTheGeometryShadersAsThePageDoes) {
    ScratchDir dir;
    const std::string common = "--track fur --headless --frames 1 --size 80x60 --scene torus ";
    CommandResult real = demoIn(dir, common + "--out real");
    ASSERT_EQ(real.exitCode, 0) << real.all();
    CommandResult r = demoIn(dir, common + "--out emulated --emulate-geometry");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("geometry shaders emulated as in the page"), std::string::npos) << r.out;
    EXPECT_EQ(real.out.find("emulated"), std::string::npos) << real.out;
    for (const char* picture :
         {"torus-shells_and_fins-frame-000.png", "torus-fur_shader-frame-000.png"}) {
        CommandResult same = runRaylab("compare " + quote((dir / "real" / picture).string()) + " " +
                                       quote((dir / "emulated" / picture).string()));
        EXPECT_EQ(same.exitCode, 0) << picture << ": " << same.all();
    }
    CommandResult differ =
        runRaylab("compare " + quote((dir / "real/torus-shells_and_fins-frame-000.png").string()) +
                  " " + quote((dir / "emulated/torus-fur_shader-frame-000.png").string()));
    EXPECT_NE(differ.exitCode, 0) << "control: the two techniques told apart";
    r = demoIn(dir, "--headless --frames 1 --size 80x60 --out rt --emulate-geometry");
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_EQ(r.err, "raylab: error: --emulate-geometry: only with --track fur (the ray tracer has "
                     "no geometry shader)\n");
    EXPECT_FALSE(fs::exists(dir / "rt"));
}

TEST(Demo, FurTrackRefusesABadSceneBeforeAnyFolderIsMade) {
    ScratchDir dir;
    writeFile(dir / "bad.json", "{\"background\": [0, 0, 0]}");
    for (const std::string& scene : {std::string("nowhere"), (dir / "bad.json").string()}) {
        CommandResult r = demoIn(dir, "--track fur --headless --scene " + quote(scene));
        EXPECT_EQ(r.exitCode, 2) << r.all();
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_EQ(entries(dir.path()), 1) << "only bad.json: no output folder";
    CommandResult r = demoIn(dir, "--track knitting --headless");
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("--track must be raytrace or fur"), std::string::npos) << r.err;
}

// The full demo's program specialised to every ray-tracing scene compiles and
// draws, a scene without a sun included (a constant uGlowSphere of -1 used
// as an array index did not compile).
TEST(Demo, TheSpecialisedProgramCompilesForEveryScene) {
    ScratchDir dir;
    int scenes = 0;
    for (const auto& e : fs::directory_iterator(sourceDir() / "assets/scenes")) {
        if (e.path().extension() != ".json") continue;
        ++scenes;
        const std::string name = e.path().stem().string();
        CommandResult r = demoIn(dir, "--stage 08 --scene " + quote(e.path()) +
                                          " --frames 1 --size 32x24 --out " + name);
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.all();
        EXPECT_EQ(entries(dir / name), 1) << name;
    }
    EXPECT_GE(scenes, 7);
}
