#pragma once
// How far a GPU frame is from the reference tracer's (reference_tracer.h):
// the error figures of `raylab bench`. Colours are compared clamped to 0..1,
// as they reach the screen. (Students need not read this file.)
#include "reference_tracer.h"

#include <vector>

namespace raylab {

struct FrameError {
    double rmse = 0;        // root mean square over every RGB channel of every pixel, 0..1
    double psnr = 0;        // 20 log10(1 / rmse) dB; +inf for an exact match
    double maxErr = 0;      // largest channel difference, 0..1
    double badPxShare = 0;  // share of pixels with a channel off by more than 1/255
};

// GPU: RGBA floats, top row first, WIDTH x HEIGHT. REFERENCE: RW x RH
// samples; when the sizes differ the GPU frame is scaled to the reference's
// size bilinearly first (so a lower resolution shows up as error). A
// non-finite GPU value counts as the largest error (1).
FrameError frameError(const std::vector<float>& gpu, int width, int height,
                      const std::vector<ReferenceSample>& reference, int rw, int rh);

// The 99th percentile of |t_gpu - t_ref| in float32 ulps of t_ref, over the
// pixels where both hit the same object (DEPTH: one float per pixel, top row
// first; IDS likewise, as floats; same size as REFERENCE).
double depthErrorP99Ulp(const std::vector<float>& depth, const std::vector<float>& ids,
                        const std::vector<ReferenceSample>& reference);

}  // namespace raylab
