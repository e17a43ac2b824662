#pragma once
// The report half of `raylab bench`: measured rows (one per scene and setting)
// turned into files - a CSV for tools, a Markdown table for people, and a
// speed-vs-error scatter plot (PNG, drawn by gnuplot in a child process).
// Text output is deterministic: the same rows give byte-identical files.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

// One measured setting of one scene. The error metrics compare the frame with
// a double-precision reference; colours are in 0..1.
struct BenchRow {
    std::string scene;
    int width = 0, height = 0, depth = 0;
    bool shadows = true;
    std::string torusSolver = "robust";  // "robust" | "closed-form"
    bool bvh = false;
    bool specialized = false;
    std::string numerics = "robust";  // "robust" | "naive"
    double frameMs = 0, compileMs = 0;
    double rmse = 0;            // 0..1
    double psnr = 0;            // dB; +inf when rmse is 0
    double maxErr = 0;          // 0..1
    double badPxShare = 0;      // 0..1
    double depthErrP99Ulp = 0;  // ulp
    // "glsl": the GPU frame. "embree": not a picture but the limit it is
    // set against - Embree casting the frame's rays (embree_caster.h) on
    // the same cores, no shading; its error fields are NaN, its frameMs is
    // NaN when this build has no Embree, its compileMs is Embree's BVH build.
    std::string engine = "glsl";
    std::string lever;     // a speed lever of the GLSL frame that is on ("" none)
    std::size_t rays = 0;  // embree: the rays cast (primary, secondary, glow, shadow)
};

// Indices (ascending) of the rows that no other row of the same scene
// dominates in (frameMs, rmse), both lower-is-better. A row dominates another
// when it is no worse in both and better in one, so exact ties are all kept.
// A row whose frameMs or rmse is NaN, infinite or negative is never on the
// front and dominates nothing: it was not measured.
std::vector<std::size_t> paretoFront(const std::vector<BenchRow>& rows);

// A short name for a row's setting, used as the plot's point labels and in
// the Markdown: the switches that are on or differ from the default, joined
// by '+' ("linear" when the BVH is off, "spec", "naive", "cf-torus", "no-shadow";
// "baseline" if none; the lever's name when one is on; "embree-cast" for
// the Embree row), then size and depth: "spec 800x600 d8".
std::string benchSettingName(const BenchRow& row);

// The part of a row's lever that changes which rays it casts: "tree-all",
// "lbuf" and "eye" change only how they are found, so "tree-all+wcut1/255" casts
// the rays of "wcut1/255" (the Embree row it is measured against).
std::string rayLever(const std::string& lever);

// scene,width,height,depth,shadows,torus_solver,bvh,specialized,numerics,
// frame_ms,compile_ms,rmse,psnr,max_err,bad_px_share,depth_err_p99_ulp,
// engine,lever,rays,pareto
// RFC 4180 (CRLF line ends, fields quoted when needed; text that a
// spreadsheet would run as a formula gets a leading apostrophe). Booleans and
// pareto as 0/1; numbers in the shortest form that reads back exactly;
// infinities as "inf" / "-inf", NaN as an empty field.
std::string benchCsv(const std::vector<BenchRow>& rows);

// A Markdown page: "# TITLE", the command line that made it, then one table
// per scene (scenes in order of first appearance, rows by frame time) with
// readable units: ms with 1 decimal, RMSE in 1/255 steps and as a number,
// PSNR in dB, bad pixels in %. Pareto rows are marked. Under a scene with
// an Embree row: the rays it cast and the ratio of the baseline GLSL frame
// (and of the fastest GLSL row at full size and depth) to Embree's time. When PLOTFILE is not
// empty the page shows that picture (a path relative to the page).
std::string benchMarkdown(const std::vector<BenchRow>& rows, const std::string& title,
                          const std::string& commandLine, const std::string& plotFile = "");

// Draws the speed-vs-error scatter plot into PNGPATH (atomically): x = frame
// time (ms, log), y = RMSE (log; rows with RMSE 0 at a floor line, labelled
// "exact"), one colour per scene, each point labelled with its setting name,
// each scene's Pareto front as a step line with its points ringed.
// GNUPLOT is run without a shell: a name is looked up on $PATH, anything with
// a '/' is used as it is. Throws Error("gnuplot not found: ...") when it is
// not there, and Error when it fails or no row can be plotted.
void writeBenchPlot(const std::vector<BenchRow>& rows, const std::filesystem::path& pngPath,
                    const std::string& title = "RayLab bench: speed vs error",
                    const std::string& gnuplot = "gnuplot");

// DIR/bench.csv, DIR/bench.md and DIR/bench.png (without PLOT: no PNG, and
// the Markdown does not show one), each atomic; DIR is created when missing.
// The text files are written first, so they are there even when the plot
// then fails (its Error is thrown after them).
void writeBenchFiles(const std::vector<BenchRow>& rows, const std::filesystem::path& dir,
                     const std::string& title, const std::string& commandLine, bool plot = true);

}  // namespace raylab
