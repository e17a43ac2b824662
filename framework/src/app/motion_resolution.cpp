#include "motion_resolution.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {
// Pixels scale with 1/d^2, so a frame that took `ms` at divisor `from` takes
// about ms * (from/to)^2 at divisor `to` (the part that does not scale, such
// as the upscaling blit, is small next to the tracing).
double predictedMs(double ms, int from, int to) {
    const double ratio = double(from) / double(to);
    return ms * ratio * ratio;
}
}  // namespace

int reducedSize(int size, int divisor) { return std::max(1, size / std::max(1, divisor)); }

void MotionResolution::setEnabled(bool on) {
    enabled_ = on;
    if (!on) divisor_ = 1;
}

void MotionResolution::update(double previousFrameMs, bool cameraMoved) {
    const int drawnAt = divisor_;
    if (drawnAt == 1) fullFrameMs_ = previousFrameMs;
    // The frame before the previous one may have been drawn at another
    // divisor; only a frame drawn at the current one tells how it performs.
    const bool measuredHere = drawnAt == previousDivisor_;
    previousDivisor_ = drawnAt;

    // The time since the previous frame is the previous frame's time.
    stillSeconds_ = cameraMoved ? 0.0 : stillSeconds_ + previousFrameMs / 1000.0;
    const bool moving = enabled_ && stillSeconds_ < kSettleSeconds;
    if (!moving) {
        divisor_ = 1;
        return;
    }
    if (drawnAt == 1) {
        // Motion begins: the divisor that brings the full frame to the target.
        const double ratio = std::sqrt(std::max(fullFrameMs_, 0.0) / kTargetMs);
        divisor_ = std::clamp(int(std::ceil(ratio)), 1, kMaxDivisor);
        return;
    }
    if (!measuredHere) return;
    if (previousFrameMs > kTargetMs * 1.25 && divisor_ < kMaxDivisor) ++divisor_;
    else if (divisor_ > 1 && predictedMs(previousFrameMs, divisor_, divisor_ - 1) < kTargetMs * 0.8)
        --divisor_;
}

}  // namespace raylab
