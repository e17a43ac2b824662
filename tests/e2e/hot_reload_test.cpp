// Shader hot reload, as the window does it: an edited file is noticed, a
// broken edit keeps the last good program running and reports file:line, a
// fixed edit takes effect.
#include "file_watcher.h"
#include "gl_context.h"
#include "paths.h"
#include "scene.h"
#include "stage_renderer.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <thread>

using namespace raylab;
using namespace raylab::test;

namespace {
// Modification times can be coarse: make sure an edit gets a new one.
void touchLater(const fs::path& file) {
    auto before = fs::last_write_time(file);
    fs::last_write_time(file, before + std::chrono::seconds(2));
}
}  // namespace

TEST(HotReload, BrokenEditKeepsTheLastGoodProgramAndFixedEditTakesEffect) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    auto context = createEglContext();
    const StageInfo& stage = findStage("01");
    Scene scene = loadScene(projectRoot() / "assets/scenes" / stage.scene);
    StageRenderer renderer(stage, labSources(stage, lab.path()), scene, 64, 48);
    Camera camera(scene.camera, scene.fovYDeg);
    renderer.render(camera, 0.0f);
    const Image good = renderer.read();

    // A rebuild from unchanged files must give the same frame: the scene's
    // constants (materials, lights, colours) belong to the new program too.
    renderer.rebuild();
    renderer.render(camera, 0.0f);
    EXPECT_EQ(renderer.read().rgba, good.rgba)
        << "a rebuilt program must get the scene's constants";

    FileWatcher watcher;
    watcher.watch(renderer.sourceFiles());
    EXPECT_FALSE(watcher.changed());

    const fs::path file = lab / "01-raycast/main.frag";
    const std::string original = readFile(file);
    writeFile(file, original + "\nthis is not GLSL\n");
    touchLater(file);
    EXPECT_TRUE(watcher.changed()) << "the edit must be noticed";
    EXPECT_FALSE(watcher.changed()) << "once per change";
    try {
        renderer.rebuild();
        FAIL() << "a broken shader must not build";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("01-raycast/main.frag:"), std::string::npos)
            << e.what();
    }
    renderer.render(camera, 0.0f);
    EXPECT_EQ(renderer.read().rgba, good.rgba) << "the last good program keeps running";

    std::string recoloured = original;
    recoloured.replace(recoloured.find("uSphereColors[hit.id]"), 21, "vec3(1.0, 0.0, 0.0)");
    writeFile(file, recoloured);
    touchLater(file);
    EXPECT_TRUE(watcher.changed());
    renderer.rebuild();
    renderer.render(camera, 0.0f);
    EXPECT_NE(renderer.read().rgba, good.rgba) << "the fixed edit takes effect";
}
