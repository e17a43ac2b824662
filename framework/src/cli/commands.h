#pragma once
// The subcommands of `raylab`, one file each (cmd_*.cpp). Each returns the
// process exit code: 0 success, 1 a check failed, 2 bad input or an error.
#include "gl_context.h"
#include "grade_options.h"
#include "stage_setup.h"

#include <string>
#include <vector>

namespace raylab {

int cmdStages();

struct RunOptions {
    bool noVsync = false;
    bool fullResolution = false;  // also while the camera moves
    int exitAfterFrames = 0;
    int walkFrames = 0;
    std::string screenshot;
};
int cmdRun(const StageOptions& stage, const RunOptions& run);

struct RenderOptions {
    std::string outFile;  // .png (a picture) or .pfm (raw floats)
    Backend backend = Backend::Auto;
    std::string view = "color";  // color, depth, normal, id, bounces, stack (debug_views.h)
    bool reference = false;      // draw with the CPU reference tracer instead of the GPU
};
int cmdRender(const StageOptions& stage, const RenderOptions& render);

// `raylab rays`: the GPU's primary rays to a file (format: ray_dump.h).
int cmdRays(const StageOptions& stage, const std::string& outFile, Backend backend);

// `raylab trace --pixel X,Y`: one pixel's path from the CPU reference tracer
// (no OpenGL context). PIXEL is "X,Y", 0,0 the top left.
int cmdTrace(const StageOptions& stage, const std::string& pixel);

struct DemoOptions {
    std::string stage;  // empty: the highest finished stage
    std::string scene;  // "lite", "pro" or a file; empty: the stage's scene
    std::string size = "800x600";
    std::string outDir;  // empty: a new folder under the current directory
    int frames = 6;
    bool headless = false;
    bool noShadows = false;
    int maxDepth = RenderSettings::kMaxDepth;
    bool noBvh = false;
    Backend backend = Backend::Auto;
    std::string track = "raytrace";  // "fur": cmd_demo_fur.cpp
    bool emulateGeometry = false;    // fur: the page's way (core/geometry_emulation.h)
};
int cmdDemo(const DemoOptions& demo);
int cmdDemoFur(const DemoOptions& demo);

struct CheckOptions {
    std::string againstDir;  // compare with these PNGs instead of the live solution
    std::string saveDir;     // write the checked images here
    Backend backend = Backend::Auto;
    double timeoutSeconds = 600.0;  // the whole check, in its child process (check_sandbox.h)
    long memoryMb = 0;              // its address space; 0: no limit
    std::string courseFile;         // the course's weights for the score (course_file.h)
    std::vector<std::string> only;  // --checks: these checks by name; empty: all
};
int cmdCheck(const StageOptions& stage, const CheckOptions& check);

// The child-process halves of `raylab grade` (not for direct use).
int cmdGradeReference(const std::string& stage, const std::string& outDir, unsigned seed);
int cmdGradeItem(const std::string& stage, const std::string& labRoot, const std::string& student,
                 const std::string& outDir, unsigned seed, const std::string& courseFile);

struct BenchOptions {
    std::string outDir;               // bench.csv, bench.md, bench.png go here (made when missing)
    bool quick = false;               // a small grid for CI: lite at 160x120, one frame per setting
    std::vector<std::string> scenes;  // empty: lite and pro (quick: lite)
    std::string size;                 // empty: 800x600 (quick: 160x120)
    int frames = 0;                   // timed frames per setting; 0: 5 (quick: 1)
    Backend backend = Backend::Auto;
    std::string commandLine;         // for the report
    std::string track = "raytrace";  // "fur": the fur track's bench (cmd_bench_fur.cpp)
    bool growth = false;  // frame and build time against object count (cmd_bench_growth.cpp)
    bool plot = true;     // false (--no-plot): the CSV and Markdown only, no gnuplot needed
};
int cmdBench(const BenchOptions& bench);
int cmdBenchFur(const BenchOptions& bench);
int cmdBenchGrowth(const BenchOptions& bench);

// The command line as typed ("raylab bench --out x"), for reports: the
// arguments main() registered with rememberProgramArguments.
std::string programCommandLine();

// True when a window can be opened (X11 or Wayland display set).
bool displayAvailable();

}  // namespace raylab
