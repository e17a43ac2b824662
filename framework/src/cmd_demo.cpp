#include "commands.h"
#include "error.h"
#include "frame_timer.h"
#include "gl_loader.h"
#include "paths.h"
#include "stage_renderer.h"
#include "viewer_app.h"

#include <cstdio>

namespace raylab {

int cmdDemo(const DemoOptions& demo) {
    const StageInfo& stage = demo.stage.empty() ? latestAvailableStage() : findStage(demo.stage);
    StageOptions options;
    options.stage = stage.id;
    options.solution = true;
    options.size = demo.size;
    StageSetup setup = resolveStageOptions(options);
    if (demo.frames < 1 || demo.frames > 10000) throw Error("--frames must be between 1 and 10000");

    if (displayAvailable() && !demo.headless) {
        std::printf("raylab: demo of stage %s in a window (Esc quits; --headless renders to a file instead)\n", stage.id.c_str());
        ViewerApp app(std::move(setup), {}, true);
        return app.run();
    }

    std::filesystem::path outDir = demo.outDir;
    std::error_code ec;
    std::filesystem::create_directories(outDir, ec);
    if (ec || !std::filesystem::is_directory(outDir)) throw Error("--out '" + demo.outDir + "': cannot create the folder");

    auto context = createHeadlessContext(demo.backend);
    StageRenderer renderer(stage, setup.sources, setup.scene, setup.size.width, setup.size.height);
    FrameTiming timing = timeFrames([&] { renderer.render(setup.camera, setup.time, setup.settings); }, 3, demo.frames);
    std::filesystem::path out = outDir / (stage.id + ".png");
    writePngAtomic(renderer.read(), out);
    std::printf("raylab demo: stage %s%s, %dx%d, %s backend, %s\n", stage.id.c_str(),
                demo.stage.empty() ? " (the highest finished stage)" : "", setup.size.width,
                setup.size.height, context->backendName().c_str(), glDescription().c_str());
    std::printf("  frame time: %s\n", timing.summary().c_str());
    std::printf("  image written to %s\n", std::filesystem::absolute(out).lexically_normal().c_str());
    return 0;
}

} // namespace raylab
