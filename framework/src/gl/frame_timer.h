#pragma once
// The single way RayLab measures a frame time: from issuing the frame until
// the GPU (or llvmpipe's threads) has finished it, on a steady clock; median
// over several frames after a warm-up. Timer queries are not used: on
// llvmpipe GL_TIME_ELAPSED misses the rasteriser threads (a query said
// 0.6 ms for a frame that took 1.5 s).
#include <functional>
#include <string>
#include <vector>

namespace raylab {

struct FrameTiming {
    double medianMs = 0, minMs = 0, maxMs = 0;
    int frames = 0;
    const char* method = "glFinish-fenced, steady clock";
    std::string summary()
        const;  // "median 12.3 ms (min 11.9, max 13.0, 9 frames; glFinish-fenced, steady clock)"
};

// Median, min and max of frame times measured one by one (timeOneFrame).
FrameTiming summarizeFrameTimes(std::vector<double> ms);

// Milliseconds from issuing drawFrame() until glFinish returns, after a
// glFinish that drains earlier work.
double timeOneFrame(const std::function<void()>& drawFrame);

}  // namespace raylab
