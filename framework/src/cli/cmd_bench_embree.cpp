// The Embree rows of `raylab bench`: see cmd_bench_embree.h.
#include "cmd_bench_embree.h"

#include "frame_timer.h"

#include <cmath>
#include <cstdio>

namespace raylab {

BenchRow embreeRow(const std::string& sceneName, Size size, const RenderSettings& full,
                   const RaySet& set, const EmbreeCaster* embree,
                   const std::vector<double>& castMs) {
    const std::vector<TracedRay>& rays = set.rays;
    BenchRow row;
    row.scene = sceneName;
    row.width = size.width;
    row.height = size.height;
    row.depth = full.maxDepth;
    row.shadows = full.shadows;
    row.bvh = true;
    row.engine = "embree";
    row.lever = set.lever;
    row.rays = rays.size();
    row.frameMs = embree ? summarizeFrameTimes(castMs).medianMs : NAN;
    row.compileMs = embree ? embree->buildMs() : NAN;
    row.rmse = row.psnr = row.maxErr = row.badPxShare = row.depthErrP99Ulp = NAN;
    return row;
}

void printEmbreeRow(const std::vector<BenchRow>& rows, const std::vector<TracedRay>& rays,
                    int threads) {
    const BenchRow& e = rows.back();
    if (std::isnan(e.frameMs)) {
        std::printf("  %-5s %-38s Embree not built (install libembree-dev, run cmake again)\n",
                    e.scene.c_str(), benchSettingName(e).c_str());
        return;
    }
    const TracedRayCounts c = countRays(rays);
    std::printf("  %-5s %-38s frame %8.1f ms  (%zu rays: %zu primary, %zu reflected/refracted, "
                "%zu glow, %zu shadow; %d threads; BVH build %.1f ms)\n",
                e.scene.c_str(), benchSettingName(e).c_str(), e.frameMs, c.total(), c.primary,
                c.secondary, c.glow, c.shadow, threads, e.compileMs);
    for (const BenchRow& r : rows)
        if (r.scene == e.scene && r.engine == "glsl" && rayLever(r.lever) == e.lever &&
            r.numerics == "robust" && r.torusSolver == "robust" && r.width == e.width &&
            r.height == e.height && r.depth == e.depth && r.shadows)
            std::printf("  %-5s %-38s / %s: %.2f x\n", e.scene.c_str(), benchSettingName(r).c_str(),
                        benchSettingName(e).c_str(), r.frameMs / e.frameMs);
}

}  // namespace raylab
