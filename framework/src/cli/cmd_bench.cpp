// `raylab bench`: speed against error. For the lite and pro scenes and a
// grid of settings it measures, in one run, the median frame time, the shader
// compile time and the error against the double-precision reference tracer,
// and writes bench.csv, bench.md and bench.png (bench_report.h).
//
// The grid changes one thing at a time from a baseline (BVH on, generic
// shader, robust numerics, depth 8, shadows on): faster settings that cost
// accuracy (less depth, no shadows, a lower resolution), settings that should
// cost nothing (specialised shader, no BVH) and settings that cost only
// accuracy (the naive numerics, the seed's torus solver). So each row says
// what one switch does. Frames of all settings are timed in turns, so the
// ratios between rows hold even on a shared, noisy machine. Every row is
// compared with the reference at full quality (depth 8, shadows on, full
// size): a lower resolution is scaled up first, so it shows as error.
// Compile times are measured with Mesa's shader cache off.
#include "bench_report.h"
#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "debug_views.h"
#include "error.h"
#include "frame_error.h"
#include "frame_timer.h"
#include "gl_loader.h"
#include "paths.h"
#include "reference_tracer.h"
#include "stage_renderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace raylab {

namespace {

struct BenchSetting {
    int width, height, depth;
    bool shadows;
    ShaderVariant variant;
};

std::vector<BenchSetting> gridFor(const Scene& scene, bool quick, int width, int height) {
    ShaderVariant base;  // BVH on, generic shader, robust numerics
    auto with = [&](auto change) {
        BenchSetting s{width, height, RenderSettings::kMaxDepth, true, base};
        change(s);
        return s;
    };
    std::vector<BenchSetting> grid = {
        with([](BenchSetting&) {}),
        with([](BenchSetting& s) { s.variant.bvh = false; }),
        with([](BenchSetting& s) { s.variant.specialized = true; }),
        with([](BenchSetting& s) { s.depth = 2; }),
    };
    if (quick) return grid;
    grid.push_back(with([](BenchSetting& s) {
        s.variant.bvh = false;
        s.variant.specialized = true;
    }));
    grid.push_back(with([](BenchSetting& s) {
        s.variant.specialized = true;
        s.shadows = false;
    }));
    grid.push_back(with([](BenchSetting& s) { s.shadows = false; }));
    grid.push_back(with([](BenchSetting& s) { s.depth = 4; }));
    grid.push_back(with([](BenchSetting& s) { s.depth = 1; }));
    grid.push_back(with([&](BenchSetting& s) {
        s.width = width / 2;
        s.height = height / 2;
    }));
    grid.push_back(with([](BenchSetting& s) { s.variant.naiveNumerics = true; }));
    if (!scene.tori.empty())
        grid.push_back(with([](BenchSetting& s) { s.variant.torusClosedForm = true; }));
    return grid;
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// One setting being measured: its renderer stays alive for the whole run,
// so that frames of every setting can be timed in turns.
struct Measured {
    BenchSetting setting;
    std::unique_ptr<StageRenderer> renderer;
    RenderSettings settings;
    double firstMs = 0;
    std::vector<double> frameMs;
};

BenchRow rowFor(const std::string& sceneName, const Scene& scene, const StageInfo& stage,
                const StageSources& sources, const Measured& m,
                const std::vector<ReferenceSample>& reference, int rw, int rh) {
    const BenchSetting& s = m.setting;
    FrameTiming timing = summarizeFrameTimes(m.frameMs);
    FrameError err =
        frameError(m.renderer->target().readFloats(), s.width, s.height, reference, rw, rh);
    BenchRow row;
    row.scene = sceneName;
    row.width = s.width;
    row.height = s.height;
    row.depth = s.depth;
    row.shadows = s.shadows;
    row.torusSolver = s.variant.torusClosedForm ? "closed-form" : "robust";
    row.bvh = s.variant.bvh;
    row.specialized = s.variant.specialized;
    row.numerics = s.variant.naiveNumerics ? "naive" : "robust";
    row.frameMs = timing.medianMs;
    row.compileMs = std::max(0.0, m.firstMs - timing.medianMs);
    row.rmse = err.rmse;
    row.psnr = err.psnr;
    row.maxErr = err.maxErr;
    row.badPxShare = err.badPxShare;

    // Hit distance of the primary rays, same program variant, full size only.
    if (s.width == rw && s.height == rh) {
        GpuViewRenderer depth(GpuView::Depth, stage, sources, scene, s.width, s.height, s.variant);
        depth.render(cameraFor(std::nullopt, scene), 0.0f, m.settings);
        std::vector<float> rgba = depth.readFloats();
        std::vector<float> t(reference.size()), id(reference.size());
        for (std::size_t i = 0; i < reference.size(); ++i) {
            t[i] = rgba[4 * i];
            id[i] = rgba[4 * i + 3] > 0.5f ? rgba[4 * i + 1] : -1.0f;
        }
        row.depthErrP99Ulp = depthErrorP99Ulp(t, id, reference);
    }
    return row;
}

// Builds every setting's program (timing compile + first frame), then times
// FRAMES frames of each in turns - setting 1, 2, ..., N, 1, 2, ... - so that
// a slow spell of a shared machine hits every setting alike.
std::vector<Measured> measureAll(const Scene& scene, const StageInfo& stage,
                                 const StageSources& sources, const std::vector<BenchSetting>& grid,
                                 int frames) {
    const Camera camera = cameraFor(std::nullopt, scene);
    std::vector<Measured> all;
    for (const BenchSetting& s : grid) {
        Measured m;
        m.setting = s;
        m.settings.maxDepth = s.depth;
        m.settings.shadows = s.shadows;
        // Compile time: building the program plus the first frame (llvmpipe
        // compiles its code on first use), less one frame's own time.
        auto start = std::chrono::steady_clock::now();
        m.renderer = std::make_unique<StageRenderer>(stage, sources, scene, s.width, s.height,
                                                     PixelFormat::Rgba32F, "", s.variant);
        timeOneFrame([&] { m.renderer->render(camera, 0.0f, m.settings); });
        m.firstMs = msSince(start);
        all.push_back(std::move(m));
    }
    for (Measured& m : all)
        timeOneFrame(
            [&] { m.renderer->render(camera, 0.0f, m.settings); });  // warm-up round, not counted
    for (int round = 0; round < frames; ++round)
        for (Measured& m : all)
            m.frameMs.push_back(
                timeOneFrame([&] { m.renderer->render(camera, 0.0f, m.settings); }));
    return all;
}

}  // namespace

int cmdBench(const BenchOptions& options) {
    if (options.track != "raytrace" && options.track != "fur")
        throw Error("--track must be raytrace or fur (not '" + options.track + "')");
    if (options.growth && options.track != "raytrace")
        throw Error("--growth measures the ray tracer: leave out --track fur");
    if (options.growth && !options.scenes.empty())
        throw Error("--growth makes its own scenes: leave out --scenes");
    if (options.growth) return cmdBenchGrowth(options);
    if (options.track == "fur") return cmdBenchFur(options);
    if (options.outDir.empty()) throw Error("--out DIR is required");
    const StageInfo& stage = demoStage();
    std::vector<std::string> scenes =
        options.quick ? std::vector<std::string>{"lite"} : std::vector<std::string>{"lite", "pro"};
    if (!options.scenes.empty()) scenes = options.scenes;
    Size size =
        parseSize(options.size.empty() ? (options.quick ? "160x120" : "800x600") : options.size);
    int frames = options.frames > 0 ? options.frames : (options.quick ? 1 : 5);
    if (frames > 1000) throw Error("--frames must be between 1 and 1000");
    // Everything that can fail on bad input fails before any measuring.
    std::vector<Scene> loaded;
    for (const std::string& name : scenes) loaded.push_back(loadScene(demoSceneFile(name)));
    // The output folder too: minutes of measuring must not end in "cannot write".
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec || !std::filesystem::is_directory(options.outDir))
        throw Error("--out '" + options.outDir + "': cannot make this folder" +
                    (ec ? ": " + ec.message() : std::string(" (a file is in the way)")));

    // Compile times are only honest without Mesa's on-disk shader cache (a
    // second run would find every program there). Set before the driver loads.
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    auto context = createHeadlessContext(options.backend);
    const StageSources sources = solutionSources(stage);
    std::vector<BenchRow> rows;
    std::printf("raylab bench: stage %s, %s backend, %s; %d timed frame%s per setting\n",
                stage.id.c_str(), context->backendName().c_str(), glDescription().c_str(), frames,
                frames == 1 ? "" : "s");
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const Scene& scene = loaded[k];
        const std::string name = std::filesystem::path(scene.file).stem().string();
        auto start = std::chrono::steady_clock::now();
        RenderSettings full;  // the reference: depth 8, shadows on
        ReferenceTracer tracer(scene, ReferenceFeatures::forStage(stage), 0.0f, full);
        std::vector<ReferenceSample> reference =
            tracer.traceImage(cameraFor(std::nullopt, scene), size.width, size.height);
        std::printf("  %s: reference %dx%d traced in %.1f s (CPU, double)\n", name.c_str(),
                    size.width, size.height, msSince(start) / 1000.0);
        std::vector<Measured> measured = measureAll(
            scene, stage, sources, gridFor(scene, options.quick, size.width, size.height), frames);
        for (const Measured& m : measured) {
            BenchRow row =
                rowFor(name, scene, stage, sources, m, reference, size.width, size.height);
            std::printf("  %-5s %-28s frame %8.1f ms  compile %7.0f ms  rmse %.5f  psnr %5.1f dB  "
                        "bad px %5.1f%%  depth p99 %.1f ulp\n",
                        name.c_str(), benchSettingName(row).c_str(), row.frameMs, row.compileMs,
                        row.rmse, row.psnr, 100.0 * row.badPxShare, row.depthErrP99Ulp);
            std::fflush(stdout);
            rows.push_back(row);
        }
    }
    const std::string title = "RayLab bench (" + glDescription() + ")";
    writeBenchFiles(rows, options.outDir, title, options.commandLine);
    std::printf("raylab bench: wrote %s/bench.csv, bench.md and bench.png\n",
                std::filesystem::absolute(options.outDir).lexically_normal().c_str());
    return 0;
}

Command benchCommand() {
    return {"bench",
            "speed against error: frame and compile times and error against the reference tracer, "
            "for the lite and pro scenes and a grid of settings (bench.csv, bench.md, bench.png)",
            [](CLI::App& cmd) {
                auto bench = std::make_shared<BenchOptions>();
                cmd.add_option("--out", bench->outDir,
                               "folder for bench.csv, bench.md and bench.png (made when missing)")
                    ->required();
                cmd.add_flag("--quick", bench->quick,
                             "a small grid (lite, 160x120, one frame per setting): a smoke test, "
                             "under a minute");
                cmd.add_option("--scenes", bench->scenes,
                               "comma-separated: lite, pro or scene files (default: lite,pro)")
                    ->delimiter(',');
                cmd.add_option("--size", bench->size,
                               "image size WIDTHxHEIGHT (default 800x600, quick 160x120)");
                cmd.add_option("--frames", bench->frames,
                               "timed frames per setting (default 5, quick 1)");
                cmd.add_flag("--growth", bench->growth,
                             "frame and BVH build time against object count (mesh triangles, "
                             "spheres), BVH against linear search (growth.csv, growth.md, "
                             "growth.png; default size 160x120, 5 frames)");
                cmd.add_option("--track", bench->track,
                               "raytrace (speed against error, bench.*) or fur (shells and fins "
                               "against the fur shader, fur.*)")
                    ->capture_default_str();
                auto backend = std::make_shared<BackendOption>(cmd);
                return std::function<int()>([=] {
                    bench->backend = backend->resolve();
                    bench->commandLine = programCommandLine();
                    return cmdBench(*bench);
                });
            }};
}

}  // namespace raylab
