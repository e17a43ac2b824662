#pragma once
// Wall time for the benches' own figures (compile times, first frames).
#include <chrono>

namespace raylab {

// Milliseconds since START.
inline double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace raylab
