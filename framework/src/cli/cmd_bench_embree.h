#pragma once
// The Embree rows of `raylab bench` (cmd_bench.cpp): Embree casting the rays
// of a GLSL frame on the CPU, as one row of the report, printed beside the
// GLSL rows it is the yardstick of.
#include "bench_report.h"
#include "cli_parse.h"
#include "embree_caster.h"
#include "reference_rays.h"
#include "render_settings.h"

#include <string>
#include <vector>

namespace raylab {

// The rays of one GLSL frame for Embree to cast: the baseline's, or those of
// a lever that casts fewer (LEVER as in leverName).
struct RaySet {
    std::string lever;
    std::vector<TracedRay> rays;
};

// An embree-cast row (bench_report.h): the median of its timed casts; NaN
// times when Embree is not built.
BenchRow embreeRow(const std::string& sceneName, Size size, const RenderSettings& full,
                   const RaySet& set, const EmbreeCaster* embree,
                   const std::vector<double>& castMs);

// Prints ROWS' last row (the Embree one) with the rays it cast and the
// scene's GLSL frames of the same rays as multiples of it.
void printEmbreeRow(const std::vector<BenchRow>& rows, const std::vector<TracedRay>& rays,
                    int threads);

}  // namespace raylab
