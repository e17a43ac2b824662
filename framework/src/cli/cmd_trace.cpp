// raylab trace: one pixel's path through the scene, bounce by bounce, from
// the CPU reference tracer (reference_tracer.h), then the path the stage's
// own shader (labs/, --lab DIR or --solution) takes there on the GPU, ray by
// ray (gpu_trace.h): the two side by side show where a student's path
// leaves the reference's. A student repository's build has no reference
// tracer: the shader's path alone.
#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "error.h"
#include "gl_context.h"
#include "gpu_trace.h"
#ifndef RAYLAB_STUDENT_BUILD
#include "reference_tracer.h"
#endif
#include "shader_program.h"
#include "track_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace raylab {

namespace {

// "X,Y": two whole numbers.
void parsePixel(const std::string& text, int& x, int& y) {
    std::istringstream in(text);
    char comma = 0;
    long long px = 0, py = 0;
    if (!(in >> px >> comma >> py) || comma != ',' || !(in >> std::ws).eof() ||
        std::llabs(px) > 1000000 || std::llabs(py) > 1000000)
        throw Error("--pixel '" + text +
                    "': expected X,Y (two whole numbers, e.g. 400,300; 0,0 is the top left)");
    x = int(px);
    y = int(py);
}

[[maybe_unused]] std::string vec(const glm::dvec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
    return buf;
}

[[maybe_unused]] int byte(double c) { return int(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

}  // namespace

int cmdTrace(const StageOptions& options, const std::string& pixel) {
    int x = 0, y = 0;
    parsePixel(pixel, x, y);
    StageSetup setup = resolveStageOptions(options);
    requireRayTracingStage(*setup.stage, "raylab trace");
    const int w = setup.size.width, h = setup.size.height;
    if (x < 0 || y < 0 || x >= w || y >= h)
        throw Error("--pixel " + pixel + ": outside the " + std::to_string(w) + "x" +
                    std::to_string(h) + " image (x 0.." + std::to_string(w - 1) + ", y 0.." +
                    std::to_string(h - 1) + ")");
    const StageInfo& stage = *setup.stage;
#ifdef RAYLAB_STUDENT_BUILD
    std::printf("raylab trace: stage %s, scene %s, %dx%d, time %g s\n", stage.id.c_str(),
                setup.scene.file.c_str(), w, h, double(setup.time));
    std::printf("your shader's path (%s): a debug build of the program records each ray "
                "findClosest() traces for pixel %d,%d (0,0 top left), in order\n",
                setup.sources.label.c_str(), x, y);
#else
    const ReferenceFeatures features = ReferenceFeatures::forStage(stage);
    ReferenceTracer tracer(setup.scene, features, setup.time, setup.settings);

    const RenderSettings& s = setup.settings;
    std::printf("raylab trace: stage %s, the solution's model on the CPU in double precision; "
                "scene %s, %dx%d, time %g s\n",
                stage.id.c_str(), setup.scene.file.c_str(), w, h, double(setup.time));
    std::printf("  settings: shadows %s, depth %d, glow %s, normal maps %s, colour mode %s\n",
                s.shadows ? "on" : "off", s.maxDepth, s.glow ? "on" : "off",
                s.normalMaps ? "on" : "off", kColorModes[s.colorMode]);
    const PrimaryRay ray = primaryRay(setup.camera, w, h, x, y);
    std::printf("pixel %d,%d (0,0 top left): primary ray from %s along %s\n", x, y,
                vec(ray.origin).c_str(), vec(ray.dir).c_str());
    std::fflush(stdout);

    std::ostringstream log;
    const ReferenceSample sample = tracer.trace(ray, &log);
    std::fputs(log.str().c_str(), stdout);
    if (sample.id >= 0)
        std::printf("primary hit: t=%.6g, id %d, normal %s\n", sample.depth, sample.id,
                    vec(sample.normal).c_str());
    else std::printf("primary hit: none\n");
    std::printf("rays traced: %d, most rays waiting on the stack: %d%s\n", sample.rays,
                sample.maxStack,
                sample.stackOverflow ? ", stack overflowed (a refracted ray was dropped)" : "");
    const glm::dvec3& c = sample.color;
    std::printf("colour: %s = %d, %d, %d of 255\n", vec(c).c_str(), byte(c.r), byte(c.g),
                byte(c.b));

    std::printf("\nyour shader's path (%s): a debug build of the program records each ray "
                "findClosest() traces for this pixel, in order\n",
                setup.sources.label.c_str());
#endif
    std::fflush(stdout);
    try {
        auto context = createHeadlessContext(Backend::Auto);
        std::fputs(traceShaderPath(stage, setup.sources, setup.scene, setup.camera, setup.time,
                                   setup.settings, w, h, x, y)
                       .c_str(),
                   stdout);
    } catch (const ShaderError& e) {
        // The student's code does not compile: the reference's path alone.
        std::printf("  not traced: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        // A scene the stage's shaders cannot draw (the reference tracer draws any).
        std::printf("  not traced: %s\n", e.what());
    }
    return 0;
}

#ifdef RAYLAB_STUDENT_BUILD
constexpr const char* kTraceAbout = "print one pixel's path through your shader, ray by ray";
#else
constexpr const char* kTraceAbout =
    "print one pixel's path bounce by bounce: the CPU reference tracer's, then your shader's";
#endif

Command traceCommand() {
    return {"trace", kTraceAbout, [](CLI::App& cmd) {
                auto stage = std::make_shared<StageOptions>();
                auto pixel = std::make_shared<std::string>();
                stage->size = "800x600";
                CLI::Option* lab = addStageOptions(cmd, *stage, true);
                cmd.add_option("--pixel", *pixel,
                               "the pixel X,Y of the --size image (0,0 top left)")
                    ->required();
                return std::function<int()>([=] {
                    stage->labGiven = lab->count() > 0;
                    return cmdTrace(*stage, *pixel);
                });
            }};
}

}  // namespace raylab
