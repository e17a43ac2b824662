#pragma once
// Colours as three doubles in [0, 1] while a texture is being computed, and
// the one place where they become 8-bit pixels. Values are the sRGB-encoded
// numbers that end up in the file (no gamma conversion): the generators pick
// colours by eye, in the same space an image viewer shows.
#include "image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace raylab::texgen {

struct Rgb {
    double r = 0, g = 0, b = 0;
};

inline Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
inline Rgb operator*(Rgb a, double k) { return {a.r * k, a.g * k, a.b * k}; }
inline Rgb operator*(Rgb a, Rgb b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }

// A colour written the way colour pickers show it, so constants read as 0..255.
inline Rgb rgb255(int r, int g, int b) { return {r / 255.0, g / 255.0, b / 255.0}; }

inline double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }
inline double mix(double a, double b, double t) { return a + (b - a) * t; }
inline Rgb mix(Rgb a, Rgb b, double t) { return a * (1.0 - t) + b * t; }

// Hermite step as in GLSL: 0 below e0, 1 above e1, smooth in between.
inline double smoothstep(double e0, double e1, double x) {
    double t = clamp01((x - e0) / (e1 - e0));
    return t * t * (3.0 - 2.0 * t);
}

// Rounds to nearest so that 0.5 encodes as 128 (the normal maps' "flat").
inline std::uint8_t toByte(double v) {
    return static_cast<std::uint8_t>(std::lround(clamp01(v) * 255.0));
}

// Opaque pixels (alpha 255); only the fin strands (fur.cpp) write their own alpha.
inline void setPixel(Image& image, int x, int y, Rgb c) {
    std::uint8_t* p = image.pixel(x, y);
    p[0] = toByte(c.r);
    p[1] = toByte(c.g);
    p[2] = toByte(c.b);
    p[3] = 255;
}

}  // namespace raylab::texgen
