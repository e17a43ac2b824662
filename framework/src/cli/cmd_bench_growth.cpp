// `raylab bench --growth`: how the frame time grows with the number of
// objects, with stage 08's BVH and with the linear search, and how long the
// BVH takes to build (growth_report.h). Two series, each in one fixed view:
//   mesh:    a sphere mesh (makeShape) of 8 to about a million triangles,
//            filling the middle of the picture, on a floor, one light;
//   spheres: 10 to 4096 spheres (what one 64 KB uniform block holds,
//            sphere_blocks.h; less where the device's blocks are smaller)
//            on a jittered grid in the same box;
//   spheres in storage blocks: the same scenes of 1000 and 4096 spheres,
//            and 10,000, with the arrays in storage blocks (OpenGL 4.3, as
//            a scene past a uniform block gets them), where the device has
//            them: side by side with the uniform blocks at 1000 and 4096.
// Both programs are the specialised ones (the scene compiled in), as the
// demo draws. The linear search stops at kLinearMaxTriangles: beyond, a
// frame takes minutes on llvmpipe and adds nothing but its slope - and
// llvmpipe's loop limiter (65535 loop iterations per pixel, see
// tests/e2e/bvh_images_test.cpp) would cut its frames short from about 30k
// triangles (a primary and a shadow ray per pixel), so they would look
// faster than they are. The spheres' linear search runs to the end: at
// 10,000 spheres its two rays a pixel stay at 20,000 iterations, below the limiter.
#include "bvh.h"
#include "command.h"
#include "commands.h"
#include "error.h"
#include "frame_timer.h"
#include "gl_loader.h"
#include "gnuplot.h"
#include "growth_report.h"
#include "growth_scenes.h"
#include "paths.h"
#include "sphere_blocks.h"
#include "stage_renderer.h"
#include "stage_setup.h"
#include "stopwatch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

namespace raylab {

namespace {

constexpr long kLinearMaxTriangles = 10000;

// One point being measured: its renderer stays alive for the whole run, so
// that the frames of all points can be timed in turns.
struct Point {
    GrowthRow row;
    std::unique_ptr<StageRenderer> renderer;
    Camera camera;
    std::vector<double> frameMs;
};

constexpr const char* kStorageSeries = "spheres in storage blocks";

Point prepare(const StageInfo& stage, const StageSources& sources, const Scene& scene,
              const std::string& series, long objects, bool bvh, int width, int height) {
    GrowthRow row;
    row.series = series;
    row.bvh = bvh;
    row.objects = objects;
    row.width = width;
    row.height = height;
    row.buildMs = NAN;
    if (bvh) {
        auto start = std::chrono::steady_clock::now();
        const Bvh tree = buildBvh(scene);
        row.buildMs = msSince(start);
        row.bvhNodes = int(tree.nodes.size());
        row.bvhDepth = tree.depth;
    }
    ShaderVariant variant;
    variant.bvh = bvh;
    variant.specialized = true;
    variant.sphereStorage = series == kStorageSeries;
    Point p{row,
            std::make_unique<StageRenderer>(stage, sources, scene, width, height,
                                            PixelFormat::Rgba32F, "", variant),
            cameraFor(std::nullopt, scene),
            {}};
    RenderSettings settings;
    timeOneFrame([&] { p.renderer->render(p.camera, 0.0f, settings); });  // compile, warm up
    return p;
}

}  // namespace

int cmdBenchGrowth(const BenchOptions& options) {
    if (options.outDir.empty()) throw Error("--out DIR is required");
    const Size size = parseSize(options.size.empty() ? "160x120" : options.size);
    const int frames = options.frames > 0 ? options.frames : (options.quick ? 1 : 5);
    if (frames > 1000) throw Error("--frames must be between 1 and 1000");
    const std::vector<long> triangles =
        options.quick ? std::vector<long>{10, 100, 1000}
                      : std::vector<long>{10, 100, 1000, 10000, 100000, 1000000};
    std::vector<int> spheres =
        options.quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000};
    // Everything that could fail at the end of a long run fails first.
    if (options.plot && !bench::gnuplotAvailable())
        throw Error(
            "gnuplot not found: install gnuplot-nox (bash install.sh --test does), or leave the "
            "plot out with --no-plot");
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec || !std::filesystem::is_directory(options.outDir))
        throw Error("--out '" + options.outDir + "': cannot make this folder");
    auto context = createHeadlessContext(options.backend);
    const StageInfo& stage = demoStage();
    const StageSources sources = solutionSources(stage);
    // The largest uniform-block scene: what the device's blocks hold, at
    // most stage 08's limit; storage blocks where the device has them
    // (sphere_blocks.h).
    const SphereArrayLimits limits = sphereArrayLimits();
    const int inBlock =
        std::min(stage.limits.spheres, limits.uniformBlockBytes / kSphereBlockStride);
    if (!options.quick) spheres.push_back(inBlock);
    std::vector<int> inStorage;
    constexpr int kMostSpheres = 10000;
    if (!options.quick && limits.storageBlockBytes / kSphereBlockStride >= kMostSpheres)
        inStorage = {1000, inBlock, kMostSpheres};
    std::printf("raylab bench --growth: stage %s, %dx%d, depth 8, shadows on, %s backend, %s; %d "
                "timed frame%s per point\n",
                stage.id.c_str(), size.width, size.height, context->backendName().c_str(),
                glDescription().c_str(), frames, frames == 1 ? "" : "s");
    // Every point's program first, then FRAMES rounds of one frame of each
    // point in turn: a slow spell of a shared machine hits every point alike.
    std::vector<Point> points;
    for (long wanted : triangles) {
        const Scene scene = growthMeshScene(wanted);
        const long n = long(meshTriangleCount(scene));
        points.push_back(prepare(stage, sources, scene, "mesh", n, true, size.width, size.height));
        if (n <= kLinearMaxTriangles)
            points.push_back(
                prepare(stage, sources, scene, "mesh", n, false, size.width, size.height));
    }
    for (int n : spheres) {
        const Scene scene = growthSphereScene(n);
        for (bool bvh : {true, false})
            points.push_back(
                prepare(stage, sources, scene, "spheres", n, bvh, size.width, size.height));
    }
    for (int n : inStorage) {
        const Scene scene = growthSphereScene(n);
        for (bool bvh : {true, false})
            points.push_back(
                prepare(stage, sources, scene, kStorageSeries, n, bvh, size.width, size.height));
    }
    const RenderSettings settings;  // depth 8, shadows on
    for (int round = 0; round < frames; ++round)
        for (Point& p : points)
            p.frameMs.push_back(
                timeOneFrame([&] { p.renderer->render(p.camera, 0.0f, settings); }));
    std::vector<GrowthRow> rows;
    for (Point& p : points) {
        p.row.frameMs = summarizeFrameTimes(p.frameMs).medianMs;
        std::printf("  %-8s %8ld  %-6s frame %9.2f ms  build %8.1f ms\n", p.row.series.c_str(),
                    p.row.objects, p.row.bvh ? "BVH" : "linear", p.row.frameMs,
                    p.row.bvh ? p.row.buildMs : 0.0);
        rows.push_back(p.row);
        p.renderer.reset();
    }
    const Growth g = growthBetween(rows, "mesh", true, 1000, 100000);
    if (std::isfinite(g.ratio))
        std::printf("  mesh, BVH: frame time %ld -> %ld triangles grows %.2fx (goal: at most 3x)\n",
                    g.from, g.to, g.ratio);
    const std::string notes =
        "Stage 08's solution, specialised programs (the scene compiled in), " +
        std::to_string(size.width) + "x" + std::to_string(size.height) +
        ", depth 8, shadows on, median of " + std::to_string(frames) +
        " frame(s) after one untimed frame, the points' frames timed in turns (round by "
        "round). Mesh: a sphere mesh (radius 1, filling the middle "
        "of the picture) on a floor, one light; the triangle counts are the sphere's "
        "tessellations nearest below 10, 100, ... The linear search is measured up to " +
        std::to_string(kLinearMaxTriangles) +
        " triangles (beyond, a frame takes minutes, and llvmpipe's loop limiter, 65535 "
        "iterations per pixel, would cut it short). Spheres: a jittered grid in the same box, "
        "10 to " +
        std::to_string(spheres.back()) +
        " (what one uniform block of the device holds), both searches to the end. " +
        (inStorage.empty() ? std::string("This device has no storage blocks. ")
                           : "Spheres in storage blocks: the same scenes with the spheres' "
                             "arrays in storage blocks (OpenGL 4.3, what a scene of more than " +
                                 std::to_string(inBlock) + " spheres gets), " +
                                 std::to_string(inStorage.front()) + " to " +
                                 std::to_string(inStorage.back()) + ". ") +
        "Build: `buildBvh` on the CPU, once.";
    writeGrowthFiles(rows, options.outDir, "RayLab growth (" + glDescription() + ")",
                     options.commandLine, notes, options.plot);
    std::printf("raylab bench --growth: wrote %s/growth.csv, growth.md%s\n",
                std::filesystem::absolute(options.outDir).lexically_normal().c_str(),
                options.plot ? " and growth.png" : " (no plot: --no-plot)");
    return 0;
}

}  // namespace raylab
