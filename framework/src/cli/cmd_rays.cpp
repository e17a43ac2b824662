// `raylab rays`: the primary rays of a frame exactly as the GPU computed them
// (format: ray_dump.h).
#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "debug_views.h"
#include "error.h"
#include "ray_dump.h"
#include "track_registry.h"

#include <cstdio>

namespace raylab {

int cmdRays(const StageOptions& options, const std::string& outFile, Backend backend) {
    if (outFile.empty()) throw Error("--out FILE is required");
    std::error_code ec;
    std::filesystem::path out(outFile);
    std::filesystem::path dir = out.parent_path().empty() ? "." : out.parent_path();
    if (!std::filesystem::is_directory(dir, ec))
        throw Error("--out '" + outFile + "': folder " + dir.string() + " does not exist");
    StageSetup setup = resolveStageOptions(options);
    requireRayTracingStage(*setup.stage, "raylab rays");

    auto context = createHeadlessContext(backend);
    const int w = setup.size.width, h = setup.size.height;
    GpuViewRenderer renderer(GpuView::Rays, *setup.stage, setup.sources, setup.scene, w, h);
    renderer.render(setup.camera, setup.time, setup.settings);
    std::vector<float> rgba = renderer.readFloats();

    RayDump dump;
    dump.width = w;
    dump.height = h;
    dump.records.resize(std::size_t(w) * std::size_t(h) * 6);
    // The camera in the scene's own coordinates (the file format holds floats).
    const glm::vec3 eye(setup.camera.pose().position);
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i) {
        float* r = &dump.records[6 * i];
        r[0] = eye.x, r[1] = eye.y, r[2] = eye.z;
        r[3] = rgba[4 * i], r[4] = rgba[4 * i + 1], r[5] = rgba[4 * i + 2];
    }
    writeRayDumpAtomic(dump, out);
    std::printf("raylab: wrote %s (%dx%d primary rays from the GPU, origin + unit direction per "
                "pixel, stage %s, %s, %s backend)\n",
                outFile.c_str(), w, h, setup.stage->id.c_str(), setup.sources.label.c_str(),
                context->backendName().c_str());
    return 0;
}

Command raysCommand() {
    return {"rays", "write the primary rays the GPU computes for every pixel to a file",
            [](CLI::App& cmd) {
                struct Options {
                    StageOptions stage;
                    std::string out;
                    Backend backend = Backend::Auto;
                };
                auto o = std::make_shared<Options>();
                o->stage.size = "800x600";
                CLI::Option* lab = addStageOptions(cmd, o->stage, true);
                cmd.add_option(
                       "--out", o->out,
                       "output file (RLRAYS01: header, then origin and direction per pixel)")
                    ->required();
                auto backend = std::make_shared<BackendOption>(cmd);
                return std::function<int()>([=] {
                    o->backend = backend->resolve();
                    o->stage.labGiven = lab->count() > 0;
                    return cmdRays(o->stage, o->out, o->backend);
                });
            }};
}

}  // namespace raylab
