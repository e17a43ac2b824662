// `raylab demo --track fur`: the two techniques of the fur track on the same
// meshes. With a display, the window on the last fur stage (T switches the
// technique, M the mesh); without one (or with --headless), a few frames of
// each scene turning, drawn with shells + fins and with the fur shader,
// written to PNG files and timed side by side (--emulate-geometry: the fins
// and strands drawn as the page draws them, core/geometry_emulation.h).
#include "command.h"
#include "commands.h"
#include "error.h"
#include "frame_timer.h"
#include "fur_renderer.h"
#include "gl_loader.h"
#include "paths.h"
#include "stage_setup.h"
#include "viewer_window.h"

#include <cstdio>
#include <ctime>

namespace raylab {

namespace {

// Scene names under assets/scenes/fur/ the demo shows by default.
const std::vector<std::string> kDemoScenes = {"sphere", "torus", "cube", "shaggy"};

std::filesystem::path furSceneFile(const std::string& name) {
    if (name.find('/') != std::string::npos || name.find(".json") != std::string::npos) return name;
    return stageSceneFile("fur/" + name + ".json");
}

std::filesystem::path outputFolder(const DemoOptions& demo) {
    if (!demo.outDir.empty()) return demo.outDir;
    char stamp[32];
    std::time_t now = std::time(nullptr);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    std::filesystem::path dir = std::string("raylab-demo-fur-") + stamp;
    for (int n = 2; std::filesystem::exists(dir); ++n)
        dir = std::string("raylab-demo-fur-") + stamp + "-" + std::to_string(n);
    return dir;
}

}  // namespace

int cmdDemoFur(const DemoOptions& demo) {
    const StageInfo& stage = demo.stage.empty() ? demoStage("fur") : findStage(demo.stage);
    if (stage.track != "fur")
        throw Error("--track fur: stage " + stage.id + " is on the " + stage.track + " track");
    if (demo.frames < 1 || demo.frames > 1000) throw Error("--frames must be between 1 and 1000");
    std::vector<std::string> names = kDemoScenes;
    if (!demo.scene.empty()) names = {demo.scene};
    // Every scene is read before anything is drawn or written.
    std::vector<std::pair<std::string, FurScene>> scenes;
    for (const std::string& n : names)
        scenes.emplace_back(std::filesystem::path(furSceneFile(n)).stem().string(),
                            loadFurScene(furSceneFile(n)));

    StageOptions options;
    options.stage = stage.id;
    options.solution = true;
    options.size = demo.size;
    options.scene = furSceneFile(names.front()).string();
    StageSetup setup = resolveStageOptions(options);
    if (displayAvailable() && !demo.headless && !demo.emulateGeometry) {
        if (windowBuiltIn()) {
            std::printf("raylab: fur demo of stage %s in a window (T: shells + fins / fur shader, "
                        "M: mesh, [ ]: shells, F: fins; Esc quits; --headless renders to files)\n",
                        stage.id.c_str());
            return openViewerWindow(std::move(setup), {});
        }
        std::printf("raylab: a headless build (RAYLAB_WINDOW=OFF): rendering to files\n");
    }

    auto context = createHeadlessContext(demo.backend);
    // Meshes and shaders too are ready before the output folder is made, so
    // that a bad OBJ file leaves nothing behind.
    std::vector<std::unique_ptr<FurRenderer>> renderers;
    for (const auto& named : scenes) {
        renderers.push_back(std::make_unique<FurRenderer>(stage, setup.sources, named.second,
                                                          setup.size.width, setup.size.height));
        if (demo.emulateGeometry) renderers.back()->setGeometryEmulation(true);
    }
    const std::filesystem::path outDir = outputFolder(demo);
    std::error_code ec;
    std::filesystem::create_directories(outDir, ec);
    if (ec || !std::filesystem::is_directory(outDir))
        throw Error("--out '" + outDir.string() + "': cannot create the folder");
    std::printf("raylab demo --track fur: stage %s, %dx%d, %s backend, %s%s\n", stage.id.c_str(),
                setup.size.width, setup.size.height, context->backendName().c_str(),
                glDescription().c_str(),
                demo.emulateGeometry ? "; geometry shaders emulated as in the page" : "");
    const float step = 0.25f;  // seconds of turning between frames
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const auto& [name, scene] = scenes[k];
        FurRenderer& renderer = *renderers[k];
        const Camera camera(scene.camera, scene.fovYDeg);
        // The techniques this stage has: the fur shader from f4 on.
        const int techniques = stage.has("fur_shader") ? kFurTechniqueCount : 1;
        std::string line;
        for (int t = 0; t < techniques; ++t) {
            RenderSettings s;
            s.furTechnique = t;
            renderer.render(camera, 0.0f, s);  // warm-up
            std::vector<double> ms;
            for (int i = 0; i < demo.frames; ++i) {
                ms.push_back(timeOneFrame([&] { renderer.render(camera, step * float(i), s); }));
                char number[16];
                std::snprintf(number, sizeof number, "%03d", i);
                writePngAtomic(renderer.read(), outDir / (name + "-" + kFurTechniques[t] +
                                                          "-frame-" + number + ".png"));
            }
            const std::string label =
                t == 1 ? std::string("fur shader")
                       : std::string(stage.has("fins") ? "shells+fins (" : "shells (") +
                             std::to_string(scene.fur.shells) + " shells)";
            char timing[32];
            std::snprintf(timing, sizeof timing, " %.1f ms", summarizeFrameTimes(ms).medianMs);
            line += "   " + label + timing;
        }
        std::printf("  %-8s %7zu triangles%s\n", name.c_str(), renderer.mesh().triangleCount(),
                    line.c_str());
    }
    std::printf("  %d frames per scene and technique written to %s\n", demo.frames,
                std::filesystem::absolute(outDir).lexically_normal().c_str());
    return 0;
}

}  // namespace raylab
