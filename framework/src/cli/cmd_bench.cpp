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
//
// Next to the GLSL rows, each scene gets an "embree-cast" row: Embree casting
// exactly the rays of that frame (exported from the reference tracer, which
// casts the same rays as the GLSL up to float rounding) on the same cores,
// timed in the same rounds - the limit the GLSL frame is measured against
// (bench.md's "x Embree" column). Without Embree in the build the row says
// so and everything else is measured as before.
#include "bench_report.h"
#include "cmd_bench_embree.h"
#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "debug_views.h"
#include "embree_caster.h"
#include "error.h"
#include "eye_cells.h"
#include "frame_error.h"
#include "frame_timer.h"
#include "gl_loader.h"
#include "gnuplot.h"
#include "light_buffer.h"
#include "paths.h"
#include "reference_tracer.h"
#include "scene_transform.h"
#include "stage_renderer.h"
#include "stopwatch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <thread>

namespace raylab {

namespace {

struct BenchSetting {
    int width, height, depth;
    bool shadows;
    ShaderVariant variant;
};

// The weight-cut lever's threshold: rays that could change no channel of
// the pixel by more than one 8-bit step per unit of the colour they gather.
constexpr double kWeightCut = ShaderVariant::kDemoWeightCut;

// "wcut1/255" for a cut of 1/255: the lever's name in the bench's rows.
// "old-path" for the tracer before the levers (RAYLAB_OLD_PATH), "tree-all"
// for the scene's triangles and discs in the BVH (RAYLAB_TREE_ALL), "shared"
// for the shared-work variants (RAYLAB_SHARED_WORK), "lbuf" for shadow rays
// through a light buffer (RAYLAB_LIGHT_BUFFER), "eye" for primary rays
// through the eye's cells (RAYLAB_EYE_CELLS). The rows with the demo's
// levers ("lbuf") also test box-like shells by their slots
// (RAYLAB_SHELL_SLOTS): the same picture, so no name of its own.
std::string leverName(const ShaderVariant& v) {
    std::string name = v.oldPath ? "old-path" : (v.treeAll ? "tree-all" : "");
    auto add = [&](const std::string& lever) { name += (name.empty() ? "" : "+") + lever; };
    if (v.weightCut > 0.0) {
        char text[32];
        std::snprintf(text, sizeof text, "wcut%g/255", v.weightCut * 255.0);
        add(text);
    }
    if (v.sharedWork) add("shared");
    if (v.lightBuffer) add("lbuf");
    if (v.eyeCells) add("eye");
    return name;
}

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
    // Speed levers against the Embree row: the old path (a glow ray for
    // every pixel, shadow rays toward lights behind the surface), the weight
    // cut alone, then with the specialised shader (the fastest choice that
    // keeps the picture).
    grid.push_back(with([](BenchSetting& s) { s.variant.oldPath = true; }));
    grid.push_back(with([](BenchSetting& s) { s.variant.weightCut = kWeightCut; }));
    grid.push_back(with([](BenchSetting& s) {
        s.variant.specialized = true;
        s.variant.weightCut = kWeightCut;
    }));
    // ... with the shared-work variants on top: the glow reuses the primary
    // ray's hit, shading skips lights behind ...
    grid.push_back(with([](BenchSetting& s) {
        s.variant.specialized = true;
        s.variant.weightCut = kWeightCut;
        s.variant.sharedWork = true;
    }));
    // ... shadow rays through a light buffer ...
    if (lightBufferSuits(scene))
        grid.push_back(with([](BenchSetting& s) {
            s.variant.specialized = true;
            s.variant.useDemoLevers();
            s.variant.eyeCells = false;
        }));
    // ... and primary rays through the eye's cells (the demo's choice).
    if (lightBufferSuits(scene) && eyeCellsSuit(scene))
        grid.push_back(with([](BenchSetting& s) {
            s.variant.specialized = true;
            s.variant.useDemoLevers();
        }));
    // The "one tree over every bounded kind", against the row above:
    // the scene's few triangles and discs in the BVH instead of a loop.
    if (!scene.triangles.empty() || !scene.discs.empty())
        grid.push_back(with([](BenchSetting& s) {
            s.variant.specialized = true;
            s.variant.weightCut = kWeightCut;
            s.variant.treeAll = true;
        }));
    return grid;
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
    row.lever = leverName(s.variant);
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
// a slow spell of a shared machine hits every setting alike. Each of
// ALSOTIMED (Embree's casts, which return their own time) takes its turn
// after the settings in every round; their times go to ALSOMS.
std::vector<Measured> measureAll(const Scene& scene, const StageInfo& stage,
                                 const StageSources& sources, const std::vector<BenchSetting>& grid,
                                 int frames, const std::vector<std::function<double()>>& alsoTimed,
                                 std::vector<std::vector<double>>& alsoMs) {
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
    for (const auto& f : alsoTimed) f();
    alsoMs.assign(alsoTimed.size(), {});
    for (int round = 0; round < frames; ++round) {
        for (Measured& m : all)
            m.frameMs.push_back(
                timeOneFrame([&] { m.renderer->render(camera, 0.0f, m.settings); }));
        for (std::size_t i = 0; i < alsoTimed.size(); ++i) alsoMs[i].push_back(alsoTimed[i]());
    }
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
    // The output folder and the plotter too: minutes of measuring must not end
    // in "cannot write" or "gnuplot not found".
    if (options.plot && !bench::gnuplotAvailable())
        throw Error(
            "gnuplot not found: install gnuplot-nox (bash install.sh --test does), or leave the "
            "plot out with --no-plot");
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
        const Camera camera = cameraFor(std::nullopt, scene);
        const std::vector<BenchSetting> grid =
            gridFor(scene, options.quick, size.width, size.height);
        // Every ray of the frame, for Embree: the baseline's, and those of
        // each lever that casts fewer (the weight cut; shared work, whose
        // glow casts no ray of its own) when the grid has it.
        std::vector<RaySet> raySets(1);
        std::vector<ReferenceSample> reference =
            tracer.traceImage(camera, size.width, size.height, &raySets[0].rays);
        std::printf("  %s: reference %dx%d traced in %.1f s (CPU, double)\n", name.c_str(),
                    size.width, size.height, msSince(start) / 1000.0);
        for (const BenchSetting& s : grid)
            if ((s.variant.weightCut > 0.0 || s.variant.sharedWork) && !s.variant.oldPath &&
                std::none_of(raySets.begin(), raySets.end(), [&](const RaySet& r) {
                    return r.lever == rayLever(leverName(s.variant));
                })) {
                ReferenceTracer cut(scene, ReferenceFeatures::forStage(stage), 0.0f, full);
                cut.setWeightCut(s.variant.weightCut);
                cut.setGlowSharesPrimaryHit(s.variant.sharedWork);
                raySets.push_back({rayLever(leverName(s.variant)), {}});
                cut.traceImage(camera, size.width, size.height, &raySets.back().rays);
            }
        std::unique_ptr<EmbreeCaster> embree;
        const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
        std::vector<std::function<double()>> casts;
        if (embreeBuilt()) {
            // The reference tracer records its rays in the scene's standard
            // frame (scene_transform.h); Embree gets the scene in that frame.
            embree = std::make_unique<EmbreeCaster>(transformScene(scene, sceneFrame(scene)));
            EmbreeAnswers answers;
            embree->cast(raySets[0].rays, threads, &answers);
            std::printf("  %s: Embree %s agrees with the reference on %.3f%% of the frame's rays\n",
                        name.c_str(), embreeVersion().c_str(),
                        100.0 * agreementWithReference(raySets[0].rays, answers));
            for (const RaySet& set : raySets)
                casts.push_back([&] { return embree->cast(set.rays, threads); });
        }
        std::vector<std::vector<double>> castMs;
        std::vector<Measured> measured =
            measureAll(scene, stage, sources, grid, frames, casts, castMs);
        for (const Measured& m : measured) {
            BenchRow row =
                rowFor(name, scene, stage, sources, m, reference, size.width, size.height);
            std::printf("  %-5s %-38s frame %8.1f ms  compile %7.0f ms  rmse %.5f  psnr %5.1f dB  "
                        "bad px %5.1f%%  depth p99 %.1f ulp\n",
                        name.c_str(), benchSettingName(row).c_str(), row.frameMs, row.compileMs,
                        row.rmse, row.psnr, 100.0 * row.badPxShare, row.depthErrP99Ulp);
            std::fflush(stdout);
            rows.push_back(row);
        }
        for (std::size_t i = 0; i < raySets.size(); ++i) {
            rows.push_back(embreeRow(name, size, full, raySets[i], embree.get(),
                                     embree ? castMs[i] : std::vector<double>{}));
            printEmbreeRow(rows, raySets[i].rays, threads);
        }
    }
    const std::string title = "RayLab bench (" + glDescription() + ")";
    writeBenchFiles(rows, options.outDir, title, options.commandLine, options.plot);
    std::printf("raylab bench: wrote %s/bench.csv, bench.md%s\n",
                std::filesystem::absolute(options.outDir).lexically_normal().c_str(),
                options.plot ? " and bench.png" : " (no plot: --no-plot)");
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
                cmd.add_flag(
                    "--no-plot", [bench](std::int64_t) { bench->plot = false; },
                    "write the CSV and Markdown only, no PNG: for a machine without "
                    "gnuplot (tools/gpu/measure.sh on a lent GPU)");
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
