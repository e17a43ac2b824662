#include "sky.h"

#include "cube_map.h"
#include "parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace raylab::texgen {

namespace {

constexpr std::uint32_t kSkySeed = 4242U;

// One layer of stars. Space is cut into cubic cells of size 1 after scaling
// directions by CELLS (the sphere then has radius CELLS); each cell holds at
// most one star at a hashed point. A star only counts if that point lies in a
// thin shell around the sphere, and it is drawn at the point's direction.
// Because the shell is thin and a star's light reaches only a short way, every
// star that can light direction d sits in the 3x3x3 block of cells around
// d * CELLS: see the bound below.
struct StarLayer {
    double cells;        // sphere radius in cells: more cells, more stars
    double probability;  // chance that a cell inside the shell has a star
    double sigma;        // star radius (Gaussian), radians
    double peak;         // brightness of the brightest star of the layer
    std::uint32_t seed;
};

// Half thickness of the shell (cells), and how far a star's light reaches in
// units of its sigma. A star that lights d is at most kShell radially and
// kReach * sigma * cells tangentially from d * cells; keeping the sum under
// one cell (checked at compile time) keeps it in the 3x3x3 block.
constexpr double kShell = 0.35;
constexpr double kReach = 3.3;
constexpr bool fitsInBlock(const StarLayer& layer) {
    return kShell + kReach * layer.sigma * layer.cells < 1.0;
}

constexpr StarLayer kStarLayers[] = {
    {40.0, 0.14, 0.0040, 0.85, kSkySeed + 100},  // many faint, small stars
    {11.0, 0.25, 0.0060, 1.60, kSkySeed + 200},  // fewer, brighter ones (overexposed core)
};
static_assert(fitsInBlock(kStarLayers[0]) && fitsInBlock(kStarLayers[1]),
              "a star layer would cut stars at cell borders");

// Star colours by temperature: blue-white, white, yellow-white, orange.
Rgb starTint(double t) {
    const Rgb blue = rgb255(178, 204, 255), white = rgb255(255, 255, 255),
              yellow = rgb255(255, 236, 196), orange = rgb255(255, 196, 140);
    if (t < 0.25) return mix(blue, white, t / 0.25);
    if (t < 0.7) return mix(white, yellow, (t - 0.25) / 0.45);
    return mix(yellow, orange, (t - 0.7) / 0.3);
}

Rgb starLight(const Vec3& d, const StarLayer& layer) {
    const double reach = kReach * layer.sigma;
    const Vec3 p = d * layer.cells;
    const int ix = static_cast<int>(std::floor(p.x)), iy = static_cast<int>(std::floor(p.y)),
              iz = static_cast<int>(std::floor(p.z));
    const double cosReach = std::cos(reach);
    Rgb sum;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int cx = ix + dx, cy = iy + dy, cz = iz + dz;
                const std::uint32_t h = hashCell(cx, cy, cz, layer.seed);
                if (unitFloat(h) >= layer.probability) continue;
                const Vec3 star(cx + hashRandom(h, 1), cy + hashRandom(h, 2),
                                cz + hashRandom(h, 3));
                const double radius = glm::length(star);
                if (std::abs(radius - layer.cells) > kShell) continue;
                const double cosAngle = glm::dot(d, star / radius);
                if (cosAngle < cosReach) continue;
                const double angle = std::acos(std::min(1.0, cosAngle));
                // Most stars faint, a few bright (brightness ~ u^4).
                const double b = layer.peak * (0.12 + 0.88 * std::pow(hashRandom(h, 4), 4.0));
                const double profile =
                    std::exp(-0.5 * (angle * angle) / (layer.sigma * layer.sigma));
                sum = sum + starTint(hashRandom(h, 5)) * (b * profile);
            }
    return sum;
}

// Faint gas clouds, denser along a tilted band (a galactic plane), in purples,
// blues and a touch of rose.
Rgb nebula(const Vec3& d) {
    const Vec3 q = d * 2.0;
    const Vec3 warp(fbm(q + Vec3(2.0, 0, 0), kSkySeed + 1, {4}),
                    fbm(q + Vec3(0, 5.0, 0), kSkySeed + 2, {4}),
                    fbm(q + Vec3(0, 0, 8.0), kSkySeed + 3, {4}));
    const double density = smoothstep(-0.15, 0.55, fbm(q + warp * 1.2, kSkySeed, {6}));
    const Vec3 bandNormal = glm::normalize(Vec3(0.35, 0.85, 0.40));
    const double across = glm::dot(d, bandNormal);
    const double band = std::exp(-across * across / 0.06);
    const double hue = 0.5 + 0.5 * fbm(d * 1.5, kSkySeed + 4, {3});
    const Rgb violet = rgb255(90, 40, 130), blue = rgb255(30, 70, 140), rose = rgb255(140, 50, 90);
    const Rgb gas =
        mix(mix(blue, violet, smoothstep(0.3, 0.6, hue)), rose, smoothstep(0.62, 0.8, hue));
    return gas * (density * density * (0.25 + 0.75 * band));
}

}  // namespace

Rgb skyColor(const Vec3& d) {
    Rgb c = rgb255(2, 3, 8) + nebula(d);
    for (const StarLayer& layer : kStarLayers) c = c + starLight(d, layer);
    return c;
}

std::array<Image, 6> skyBox(int size) {
    std::array<Image, 6> faces;
    for (int face = 0; face < 6; ++face) {
        faces[std::size_t(face)] = Image(size, size);
        forEachRow(size, [&](int y) {
            for (int x = 0; x < size; ++x)
                setPixel(faces[std::size_t(face)], x, y,
                         skyColor(cubeFaceDirection(face, x, y, size)));
        });
    }
    return faces;
}

}  // namespace raylab::texgen
