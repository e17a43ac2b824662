// `raylab demo`: the full solution. With a display, the interactive window;
// without one (or with --headless), a short fly-through rendered to PNG files
// and timed.
#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "error.h"
#include "fly_through.h"
#include "frame_timer.h"
#include "gl_loader.h"
#include "paths.h"
#include "stage_renderer.h"
#include "track_registry.h"
#include "viewer_window.h"

#include <cstdio>
#include <ctime>
#include <string>

namespace raylab {

namespace {

// A folder that did not exist: raylab-demo-SCENE-YYYYmmdd-HHMMSS[-N].
std::filesystem::path newOutputFolder(const std::string& sceneName) {
    char stamp[32];
    std::time_t now = std::time(nullptr);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    std::string base = "raylab-demo-" + sceneName + "-" + stamp;
    std::filesystem::path dir = base;
    for (int n = 2; std::filesystem::exists(dir); ++n) dir = base + "-" + std::to_string(n);
    return dir;
}

std::filesystem::path prepareOutputFolder(const DemoOptions& demo, const std::string& sceneName) {
    std::filesystem::path dir =
        demo.outDir.empty() ? newOutputFolder(sceneName) : std::filesystem::path(demo.outDir);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw Error("--out '" + dir.string() + "': cannot create the folder");
    return dir;
}

std::string frameName(int i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%03d.png", i);
    return name;
}

}  // namespace

int cmdDemo(const DemoOptions& demo) {
    if (demo.track == "fur") return cmdDemoFur(demo);
    if (demo.emulateGeometry)
        throw Error("--emulate-geometry: only with --track fur (the ray tracer has no geometry "
                    "shader)");
    if (demo.track != "raytrace")
        throw Error("--track must be raytrace or fur (not '" + demo.track + "')");
    const StageInfo& stage = demo.stage.empty() ? demoStage() : findStage(demo.stage);
    requireRayTracingStage(stage, "raylab demo --stage");
    StageOptions options;
    options.stage = stage.id;
    options.solution = true;
    options.size = demo.size;
    options.scene = demoSceneFile(demo.scene);
    options.noShadows = demo.noShadows;
    options.maxDepth = demo.maxDepth;
    StageSetup setup = resolveStageOptions(options);
    if (demo.frames < 1 || demo.frames > 1000) throw Error("--frames must be between 1 and 1000");
    const std::string sceneName = std::filesystem::path(setup.scene.file).stem().string();

    if (displayAvailable() && !demo.headless) {
        if (windowBuiltIn()) {
            std::printf("raylab: demo of stage %s, scene %s, in a window (Esc quits; --headless "
                        "renders to files instead)\n",
                        stage.id.c_str(), setup.scene.file.c_str());
            return openViewerWindow(std::move(setup), {});
        }
        std::printf("raylab: a headless build (RAYLAB_WINDOW=OFF): rendering to files\n");
    }

    // Everything that can fail on bad input (scene, shaders) fails before the
    // output folder is made.
    auto context = createHeadlessContext(demo.backend);
    ShaderVariant variant = ShaderVariant::fastestFor(setup.scene);
    if (demo.noBvh) variant.bvh = false;
    // The demo runs the solution, so it may use the bench's weight-cut
    // variant of trace.glsl and the shared-work variants of the glow and
    // the shading (a student's files are never replaced).
    variant.useDemoLevers();
    StageRenderer renderer(stage, setup.sources, setup.scene, setup.size.width, setup.size.height,
                           PixelFormat::Rgba8, "", variant);
    const std::filesystem::path outDir = prepareOutputFolder(demo, sceneName);

    const FlyThrough path;
    const CameraPose start = setup.camera.pose();
    auto drawFrame = [&](int i) {
        Camera camera(path.poseAt(start, i), setup.scene.fovYDeg);
        renderer.render(camera, path.timeAt(setup.time, i), setup.settings);
    };
    drawFrame(0);  // warm-up: the driver finishes compiling on first use
    std::vector<double> ms;
    for (int i = 0; i < demo.frames; ++i) {
        ms.push_back(timeOneFrame([&] { drawFrame(i); }));
        writePngAtomic(renderer.read(), outDir / frameName(i));  // read back outside the timed part
    }
    FrameTiming timing = summarizeFrameTimes(ms);
    // The levers this scene's program got (each keeps the picture or bounds its error).
    std::string levers = "rays under 1/255 of the pixel not traced, shared work (glow and lights)";
    if (variant.usesLightBuffer(setup.scene)) levers += ", shadow rays through a light buffer";
    if (variant.usesEyeCells(setup.scene)) levers += ", primary rays through the eye's cells";
    if (variant.usesShellSlots(setup.scene)) levers += ", box-like shells by the faces met first";
    std::printf("raylab demo: stage %s, scene %s, %dx%d, depth %d, shadows %s, %s, specialised "
                "shader, %s, %s backend, %s\n",
                stage.id.c_str(), setup.scene.file.c_str(), setup.size.width, setup.size.height,
                setup.settings.maxDepth, setup.settings.shadows ? "on" : "off",
                variant.bvh ? "BVH" : "linear search", levers.c_str(),
                context->backendName().c_str(), glDescription().c_str());
    std::printf("  frame time: %s\n", timing.summary().c_str());
    std::printf("  %d frame%s written to %s\n", demo.frames, demo.frames == 1 ? "" : "s",
                std::filesystem::absolute(outDir).lexically_normal().c_str());
    return 0;
}

Command demoCommand() {
    return {
        "demo", "run the full solution; without a display render it to an image and time it",
        [](CLI::App& cmd) {
            auto demo = std::make_shared<DemoOptions>();
            cmd.add_option("--stage", demo->stage,
                           "show this stage's solution (default: the highest finished stage)");
            cmd.add_option("--size", demo->size, "image size WIDTHxHEIGHT")->capture_default_str();
            cmd.add_option("--scene", demo->scene,
                           "lite, pro or a scene file (default: the stage's scene); with --track "
                           "fur: sphere, torus, cube, shaggy, coarse, squashed or a file (default: "
                           "the first four)");
            cmd.add_option("--track", demo->track,
                           "raytrace (the full ray tracer) or fur (shells and fins against the fur "
                           "shader)")
                ->capture_default_str();
            cmd.add_option("--out", demo->outDir,
                           "folder for the headless frames (default: a new raylab-demo-SCENE-TIME "
                           "folder here)");
            cmd.add_option("--frames", demo->frames,
                           "headless: frames of the fly-through to render and time (after one "
                           "warm-up frame)")
                ->capture_default_str();
            cmd.add_flag("--no-shadows", demo->noShadows, "shadows off (key 1 in the window)");
            cmd.add_option("--depth", demo->maxDepth,
                           "rays per path, 1..8 (arrow keys in the window)")
                ->capture_default_str();
            cmd.add_flag("--headless", demo->headless,
                         "render to a file even when a display is available");
            cmd.add_flag("--no-bvh", demo->noBvh,
                         "stage 08: test every sphere for every ray instead of walking the BVH "
                         "(used from 32 spheres on)");
            cmd.add_flag("--emulate-geometry", demo->emulateGeometry,
                         "--track fur, headless: draw fins and strands as the page does (the "
                         "geometry shaders rewritten into vertex shaders), to time that way "
                         "against the real geometry shaders");
            auto backend = std::make_shared<BackendOption>(cmd);
            return std::function<int()>([=] {
                demo->backend = backend->resolve();
                return cmdDemo(*demo);
            });
        }};
}

}  // namespace raylab
