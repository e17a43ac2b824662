#include "frame_timer.h"

#include "gl.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace raylab {

std::string FrameTiming::summary() const {
    char buf[160];
    std::snprintf(buf, sizeof buf, "median %.2f ms (min %.2f, max %.2f, %d frames; %s)", medianMs, minMs, maxMs, frames, method);
    return buf;
}

FrameTiming timeFrames(const std::function<void()>& drawFrame, int warmup, int frames) {
    using Clock = std::chrono::steady_clock;
    for (int i = 0; i < warmup; ++i) drawFrame();
    glFinish();
    std::vector<double> ms;
    for (int i = 0; i < frames; ++i) {
        auto start = Clock::now();
        drawFrame();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    FrameTiming t;
    t.frames = frames;
    if (ms.empty()) return t;
    std::sort(ms.begin(), ms.end());
    t.minMs = ms.front();
    t.maxMs = ms.back();
    t.medianMs = ms.size() % 2 ? ms[ms.size() / 2] : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
    return t;
}

} // namespace raylab
