#include "frame_timer.h"

#include "gl.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace raylab {

std::string FrameTiming::summary() const {
    char buf[160];
    std::snprintf(buf, sizeof buf, "median %.2f ms (min %.2f, max %.2f, %d frames; %s)", medianMs,
                  minMs, maxMs, frames, method);
    return buf;
}

double timeOneFrame(const std::function<void()>& drawFrame) {
    using Clock = std::chrono::steady_clock;
    glFinish();
    auto start = Clock::now();
    drawFrame();
    glFinish();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

FrameTiming summarizeFrameTimes(std::vector<double> ms) {
    FrameTiming t;
    t.frames = int(ms.size());
    if (ms.empty()) return t;
    std::sort(ms.begin(), ms.end());
    t.minMs = ms.front();
    t.maxMs = ms.back();
    t.medianMs =
        ms.size() % 2 ? ms[ms.size() / 2] : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
    return t;
}

}  // namespace raylab
