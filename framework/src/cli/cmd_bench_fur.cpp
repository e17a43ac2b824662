// `raylab bench --track fur`: the source thesis's comparison measured here.
// On one mesh (the sphere of fur/sphere.json) at a series of tessellations it
// times shells + fins at several shell counts and the fur shader, side by
// side in one run (frames of every setting timed in turns, so the ratios hold
// on a shared machine), and compares each shell count's picture with one
// drawn with many shells (kReferenceShells). Writes fur.csv, fur.md, fur.png.
#include "command.h"
#include "commands.h"
#include "error.h"
#include "frame_timer.h"
#include "fur_renderer.h"
#include "fur_report.h"
#include "gl_loader.h"
#include "gnuplot.h"
#include "image_compare.h"
#include "mesh_shapes.h"
#include "paths.h"
#include "stage_setup.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace raylab {

namespace {

constexpr int kReferenceShells = 64;
const char* const kBenchScene = "fur/sphere.json";

struct FurSetting {
    int shells;
    bool fins;
    int technique;  // index into kFurTechniques
};

std::size_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * std::size_t(sysconf(_SC_PAGESIZE));
}

double rmseOf(const Image& a, const Image& b) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        const double d = (double(a.rgba[i]) - double(b.rgba[i])) / 255.0;
        sum += d * d;
        ++n;
    }
    return n ? std::sqrt(sum / double(n)) : 0.0;
}

std::string limitsNotes(const FurRenderer& r) {
    const StrandBudget& budget = r.strandBudget();
    return "Mesh: the sphere of `assets/scenes/" + std::string(kBenchScene) +
           "` at several tessellations, seen from its camera. Quality: each picture against "
           "shells + fins with " +
           std::to_string(kReferenceShells) +
           " shells of the same mesh and view (RMSE over RGB; pixels off: the graders' metric, "
           "more than 8/255 from every pixel of the reference's 3x3 neighbourhood). The fur "
           "shader draws another picture altogether (strands, not layers), so it has no error "
           "against the shells.\n\n"
           "What each technique needs (the thesis's \"technical constraints\"):\n\n"
           "| technique | needs | limits here |\n| --- | --- | --- |\n"
           "| shells | vertex and fragment shaders, blending (OpenGL 2.0, WebGL 1) | - |\n"
           "| fins | a geometry shader with `lines_adjacency` input (OpenGL 3.2; not in WebGL 2 "
           "or OpenGL ES 3.0) and an adjacency index buffer | 4 vertices per edge |\n"
           "| fur shader | a geometry shader that writes line strips (OpenGL 3.2) | "
           "GL_MAX_GEOMETRY_OUTPUT_VERTICES " +
           std::to_string(budget.maxOutputVertices) + ", GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS " +
           std::to_string(budget.maxTotalComponents) + ": " + budget.describe() + " |";
}

}  // namespace

int cmdBenchFur(const BenchOptions& options) {
    if (options.outDir.empty()) throw Error("--out DIR is required");
    if (!options.scenes.empty())
        throw Error("--scenes is for the ray tracer's bench; the fur bench draws " +
                    std::string(kBenchScene));
    const StageInfo& stage = demoStage("fur");
    const Size size =
        parseSize(options.size.empty() ? (options.quick ? "160x120" : "800x600") : options.size);
    const int frames = options.frames > 0 ? options.frames : (options.quick ? 1 : 5);
    if (frames > 1000) throw Error("--frames must be between 1 and 1000");
    const std::vector<long> triangles =
        options.quick ? std::vector<long>{200, 2000}
                      : std::vector<long>{100, 1000, 5000, 20000, 50000, 200000};
    const std::vector<FurSetting> settings =
        options.quick
            ? std::vector<FurSetting>{{16, true, 0}, {1, false, 1}}
            : std::vector<FurSetting>{
                  {8, true, 0}, {16, true, 0}, {32, true, 0}, {32, false, 0}, {1, false, 1}};
    const FurScene scene = loadFurScene(stageSceneFile(kBenchScene));
    // Everything that could fail at the end of a long run fails first, and
    // before the output folder exists.
    if (options.plot && !bench::gnuplotAvailable())
        throw Error(
            "gnuplot not found: install gnuplot-nox (bash install.sh --test does), or leave the "
            "plot out with --no-plot");
    auto context = createHeadlessContext(options.backend);
    FurRenderer renderer(stage, solutionSources(stage), scene, size.width, size.height);
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec || !std::filesystem::is_directory(options.outDir))
        throw Error("--out '" + options.outDir + "': cannot make this folder");
    const Camera camera(scene.camera, scene.fovYDeg);
    std::printf("raylab bench --track fur: stage %s, %dx%d, %s backend, %s; %d timed frame%s per "
                "setting\n",
                stage.id.c_str(), size.width, size.height, context->backendName().c_str(),
                glDescription().c_str(), frames, frames == 1 ? "" : "s");
    std::vector<FurRow> rows;
    for (long wanted : triangles) {
        renderer.setMesh(makeShape("sphere", detailForTriangles("sphere", wanted)));
        const long tris = long(renderer.mesh().triangleCount());
        auto settingsFor = [](const FurSetting& f) {
            RenderSettings s;
            s.shells = f.shells;
            s.fins = f.fins;
            s.furTechnique = f.technique;
            return s;
        };
        RenderSettings reference = settingsFor({kReferenceShells, true, 0});
        renderer.render(camera, 0.0f, reference);
        const Image referenceImage = renderer.read();
        // Warm-up (the driver finishes compiling on first use), then rounds
        // in which every setting draws one timed frame.
        std::vector<std::vector<double>> times(settings.size());
        for (const FurSetting& f : settings) renderer.render(camera, 0.0f, settingsFor(f));
        for (int round = 0; round < frames; ++round)
            for (std::size_t i = 0; i < settings.size(); ++i)
                times[i].push_back(
                    timeOneFrame([&] { renderer.render(camera, 0.0f, settingsFor(settings[i])); }));
        for (std::size_t i = 0; i < settings.size(); ++i) {
            const FurSetting& f = settings[i];
            FurRow row;
            row.technique = kFurTechniques[f.technique];
            row.mesh = "sphere";
            row.triangles = tris;
            row.shells = f.shells;
            row.fins = f.fins;
            row.frameMs = summarizeFrameTimes(times[i]).medianMs;
            row.bufferBytes = renderer.gpuBytes(settingsFor(f));
            renderer.render(camera, 0.0f, settingsFor(f));
            row.rssBytes = residentBytes();
            if (f.technique == 0) {
                const Image mine = renderer.read();
                row.rmse = rmseOf(mine, referenceImage);
                row.badPxShare =
                    compareImages(mine, referenceImage, CompareTolerance{}.channel).badShare;
            } else {
                row.rmse = row.badPxShare = NAN;
            }
            std::printf("  %7ld triangles  %-16s frame %8.2f ms  buffers %6.2f MiB  rmse %s\n",
                        tris, furSeriesName(row).c_str(), row.frameMs,
                        double(row.bufferBytes) / 1048576.0,
                        std::isfinite(row.rmse) ? std::to_string(row.rmse * 255.0).c_str() : "-");
            std::fflush(stdout);
            rows.push_back(row);
        }
    }
    const std::string title = "RayLab fur bench (" + glDescription() + ", " +
                              std::to_string(size.width) + "x" + std::to_string(size.height) + ")";
    writeFurFiles(rows, options.outDir, title, options.commandLine, limitsNotes(renderer),
                  options.plot);
    std::printf("raylab bench: wrote %s/fur.csv, fur.md%s\n",
                std::filesystem::absolute(options.outDir).lexically_normal().c_str(),
                options.plot ? " and fur.png" : " (no plot: --no-plot)");
    return 0;
}

}  // namespace raylab
