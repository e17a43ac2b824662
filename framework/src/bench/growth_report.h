#pragma once
// The report of `raylab bench --growth`: frame time and BVH build time
// against the number of objects (the triangles of one mesh in a fixed view,
// and a cloud of spheres), with the BVH and with the linear search, as
// growth.csv, growth.md and growth.png. Text output is deterministic: the
// same rows give the same files.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct GrowthRow {
    std::string series;  // "mesh" (triangles of one sphere mesh) or "spheres"
    bool bvh = true;     // false: the linear search
    long objects = 0;    // triangles or spheres
    int width = 0, height = 0;
    double frameMs = 0;  // median
    double buildMs = 0;  // building the BVH on the CPU (NaN for the linear search)
    int bvhNodes = 0, bvhDepth = 0;
};

// "mesh, BVH", "spheres, linear"
std::string growthSeriesName(const GrowthRow& row);

// series,search,objects,width,height,frame_ms,build_ms,bvh_nodes,bvh_depth
// (RFC 4180, CRLF; NaN as an empty field).
std::string growthCsv(const std::vector<GrowthRow>& rows);

// How much the frame time of SERIES (BVH or linear) grows from the row
// nearest FROM objects to the row nearest TO (nearest by ratio, and within a
// factor of 2: a sphere mesh has 960 or 9800 triangles, not 1000 or 10000):
// their frame-time ratio, with the two object counts; ratio NaN when no
// row is that near.
struct Growth {
    long from = 0, to = 0;
    double ratio = NAN;
};
Growth growthBetween(const std::vector<GrowthRow>& rows, const std::string& series, bool bvh,
                     long from, long to);

// "# TITLE", the command, NOTES, the plot, the 1k -> 100k growth against
// the goal (at most 3x), then per series a table of frame times with and
// without the BVH, their ratio and the build time.
std::string growthMarkdown(const std::vector<GrowthRow>& rows, const std::string& title,
                           const std::string& commandLine, const std::string& notes,
                           const std::string& plotFile = "");

// growth.png: frame and build time (ms, log) against objects (log). Throws
// Error like writeBenchPlot (gnuplot missing or failing).
void writeGrowthPlot(const std::vector<GrowthRow>& rows, const std::filesystem::path& pngPath,
                     const std::string& title, const std::string& gnuplot = "gnuplot");

// DIR/growth.csv, DIR/growth.md, then DIR/growth.png (not without PLOT),
// each atomic.
void writeGrowthFiles(const std::vector<GrowthRow>& rows, const std::filesystem::path& dir,
                      const std::string& title, const std::string& commandLine,
                      const std::string& notes, bool plot = true);

}  // namespace raylab
