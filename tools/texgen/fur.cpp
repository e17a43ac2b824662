#include "fur.h"

#include "color.h"
#include "noise.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>

namespace raylab::texgen {

Image furColor(int size) {
    const std::uint32_t seed = 4242U;
    const Rgb base = rgb255(150, 98, 56), dark = rgb255(70, 42, 24), light = rgb255(214, 176, 128);
    Image out(size, size);
    forEachRow(size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = (y + 0.5) / size;
            // Stripes around the body (along u), wobbling with noise; whole
            // periods per tile so the texture wraps.
            const double wobble = 0.35 * tileableFbm(u, v, 4, seed, 4);
            const double stripe = 0.5 + 0.5 * std::sin(2.0 * M_PI * (6.0 * u + wobble));
            const double patch = 0.5 + 0.5 * tileableFbm(u, v, 3, seed + 1, 3);
            Rgb c = mix(base, dark, smoothstep(0.55, 0.9, stripe));
            c = mix(c, light, 0.45 * smoothstep(0.6, 0.85, patch));
            c = c * (0.92 + 0.16 * cellRandom(x, y, 0, seed + 2, 0));  // per-hair variation
            setPixel(out, x, y, c);
        }
    });
    return out;
}

Image furPattern(int size) {
    const std::uint32_t seed = 99U;
    Image out(size, size);
    forEachRow(size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            // About two texels in three hold a hair; its height is at least
            // 0.3 so that every hair shows in the lower shells.
            double h = 0.0;
            if (cellRandom(x, y, 0, seed, 0) < 0.65)
                h = 0.3 + 0.7 * std::sqrt(cellRandom(x, y, 0, seed, 1));
            setPixel(out, x, y, Rgb{h, h, h});
        }
    });
    return out;
}

Image furFin(int width, int height) {
    const std::uint32_t seed = 321U;
    Image out(width, height);
    // Strands: a root position along the width, a height and a lean; each
    // covers a little more than a pixel and thins toward its tip.
    const int strands = width / 2;
    std::vector<double> coverage(std::size_t(width) * std::size_t(height), 0.0);
    for (int s = 0; s < strands; ++s) {
        const double root = width * cellRandom(s, 0, 0, seed, 0);
        const double length = 0.55 + 0.45 * cellRandom(s, 0, 0, seed, 1);
        const double lean = (cellRandom(s, 0, 0, seed, 2) - 0.5) * 0.25 * width / strands * 8.0;
        for (int y = 0; y < height; ++y) {
            // y = 0 is the top row of the file; GL shows the last row at v = 0.
            const double t = 1.0 - (y + 0.5) / height;  // 0 at the root
            if (t > length) continue;
            const double centre = root + lean * t * t;
            const double halfWidth = 0.9 * (1.0 - t / length) + 0.25;
            for (int dx = -2; dx <= 2; ++dx) {
                int x = int(std::floor(centre)) + dx;
                const double d = std::fabs(x + 0.5 - centre);
                const double c = std::clamp(halfWidth + 0.5 - d, 0.0, 1.0);
                x = ((x % width) + width) % width;  // strands wrap around the tile
                double& cell = coverage[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                cell = 1.0 - (1.0 - cell) * (1.0 - c);
            }
        }
    }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = out.pixel(x, y);
            p[0] = p[1] = p[2] = 255;
            p[3] = std::uint8_t(std::lround(
                255.0 * coverage[std::size_t(y) * std::size_t(width) + std::size_t(x)]));
        }
    return out;
}

}  // namespace raylab::texgen
