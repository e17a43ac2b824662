#include "patterns.h"

#include "color.h"
#include "noise.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>

namespace raylab::texgen {

Image tiles(int size) {
    const std::uint32_t seed = 777U;
    // An even number of tiles per side keeps the checker alternating across
    // the wrap.
    const int tilesPerSide = 4;
    const double tileSize = double(size) / tilesPerSide;
    const Rgb lightStone = rgb255(206, 194, 170), darkStone = rgb255(74, 80, 84),
              mortar = rgb255(120, 114, 104);
    Image out(size, size);
    forEachRow(size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            const int tx = static_cast<int>(px / tileSize), ty = static_cast<int>(py / tileSize);
            // Distance to the nearest joint in pixels; joints lie on the tile
            // borders, including the image border, which the wrap continues.
            const double fx = std::fmod(px, tileSize), fy = std::fmod(py, tileSize);
            const double edge = std::min(std::min(fx, tileSize - fx), std::min(fy, tileSize - fy));
            const double u = px / size, v = py / size;
            // Each tile cut from a slightly different stone; grain at two scales.
            const double tileShade = 0.94 + 0.12 * cellRandom(tx, ty, 0, seed, 0);
            const double cloud = tileableFbm(u, v, 8, seed + 1, 4);
            const double grain = tileableFbm(u, v, 64, seed + 2, 2);
            Rgb stone = ((tx + ty) % 2 == 0) ? lightStone : darkStone;
            stone = stone * (tileShade * (1.0 + 0.10 * cloud + 0.06 * grain));
            // Slightly worn, darker rim next to the joint suggests a bevel.
            stone = stone * (0.88 + 0.12 * smoothstep(1.5, 6.0, edge));
            const Rgb joint = mortar * (1.0 + 0.12 * grain);
            setPixel(out, x, y, mix(joint, stone, smoothstep(1.0, 2.2, edge)));
        }
    });
    return out;
}

Image marble(int size) {
    const std::uint32_t seed = 31337U;
    const double pi = 3.14159265358979323846;
    const Rgb white = rgb255(238, 236, 230), cloudy = rgb255(206, 206, 208),
              vein = rgb255(84, 92, 96), halo = rgb255(176, 178, 180);
    Image out(size, size);
    forEachRow(size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = (y + 0.5) / size;
            // The classic marble: a sine across the slab bent by turbulence.
            // Whole waves per tile (1 along u, 2 along v) keep it periodic.
            const double turbulence = tileableFbm(u, v, 2, seed, 5, 0.5);
            const double wave = std::sin(2.0 * pi * (1.0 * u + 2.0 * v) + 5.0 * turbulence);
            const double mainVein = std::exp(-std::abs(wave) * 10.0);
            const double veinHalo = std::exp(-std::abs(wave) * 2.5);
            // Thinner secondary veins in another direction.
            const double turbulence2 = tileableFbm(u, v, 3, seed + 1, 5, 0.5);
            const double wave2 = std::sin(2.0 * pi * (-2.0 * u + 1.0 * v) + 5.0 * turbulence2);
            const double thinVein = 0.5 * std::exp(-std::abs(wave2) * 24.0);
            const double haze = 0.5 + 0.5 * tileableFbm(u, v, 4, seed + 2, 4);
            Rgb color = mix(white, cloudy, smoothstep(0.35, 0.8, haze));
            color = mix(color, halo, 0.35 * veinHalo);
            color = mix(color, vein, clamp01(std::max(mainVein, thinVein)));
            setPixel(out, x, y, color);
        }
    });
    return out;
}

}  // namespace raylab::texgen
