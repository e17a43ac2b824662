#include "frame_error.h"

#include "error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab {

namespace {

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

// Channel C of the GPU frame at the reference pixel (x, y), bilinear when
// the frame has another size (pixel centres onto pixel centres).
double sampleGpu(const std::vector<float>& gpu, int w, int h, int rw, int rh, int x, int y, int c) {
    auto at = [&](int px, int py) {
        return double(
            gpu[(std::size_t(py) * std::size_t(w) + std::size_t(px)) * 4 + std::size_t(c)]);
    };
    if (w == rw && h == rh) return at(x, y);
    double sx = std::clamp((x + 0.5) * w / rw - 0.5, 0.0, double(w - 1));
    double sy = std::clamp((y + 0.5) * h / rh - 0.5, 0.0, double(h - 1));
    int x0 = int(sx), y0 = int(sy);
    int x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
    double fx = sx - x0, fy = sy - y0;
    double top = at(x0, y0) * (1 - fx) + at(x1, y0) * fx;
    double bottom = at(x0, y1) * (1 - fx) + at(x1, y1) * fx;
    return top * (1 - fy) + bottom * fy;
}

}  // namespace

FrameError frameError(const std::vector<float>& gpu, int width, int height,
                      const std::vector<ReferenceSample>& reference, int rw, int rh) {
    if (gpu.size() != std::size_t(width) * std::size_t(height) * 4 ||
        reference.size() != std::size_t(rw) * std::size_t(rh) || rw <= 0 || rh <= 0)
        throw Error("frameError: image sizes do not match their data");
    FrameError e;
    double sumSq = 0;
    long bad = 0;
    for (int y = 0; y < rh; ++y) {
        for (int x = 0; x < rw; ++x) {
            const glm::dvec3& ref =
                reference[std::size_t(y) * std::size_t(rw) + std::size_t(x)].color;
            double worst = 0;
            for (int c = 0; c < 3; ++c) {
                double g = sampleGpu(gpu, width, height, rw, rh, x, y, c);
                double d = std::isfinite(g) ? std::fabs(clamp01(g) - clamp01(ref[c])) : 1.0;
                sumSq += d * d;
                worst = std::max(worst, d);
            }
            e.maxErr = std::max(e.maxErr, worst);
            if (worst > 1.0 / 255.0) ++bad;
        }
    }
    const double n = double(rw) * double(rh);
    e.rmse = std::sqrt(sumSq / (3.0 * n));
    e.psnr = e.rmse > 0 ? 20.0 * std::log10(1.0 / e.rmse) : std::numeric_limits<double>::infinity();
    e.badPxShare = double(bad) / n;
    return e;
}

double depthErrorP99Ulp(const std::vector<float>& depth, const std::vector<float>& ids,
                        const std::vector<ReferenceSample>& reference) {
    if (depth.size() != reference.size() || ids.size() != reference.size())
        throw Error("depthErrorP99Ulp: sizes do not match");
    std::vector<double> ulps;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const ReferenceSample& r = reference[i];
        if (r.id < 0 || int(std::lround(ids[i])) != r.id || !(r.depth > 0)) continue;
        float t = float(r.depth);
        double ulp = double(std::nextafter(t, std::numeric_limits<float>::infinity()) - t);
        ulps.push_back(std::fabs(double(depth[i]) - r.depth) / ulp);
    }
    if (ulps.empty()) return 0;
    std::size_t k =
        std::min(ulps.size() - 1, std::size_t(std::ceil(0.99 * double(ulps.size()))) - 1);
    std::nth_element(ulps.begin(), ulps.begin() + long(k), ulps.end());
    return ulps[k];
}

}  // namespace raylab
