#include "planets.h"

#include "color.h"
#include "normal_map.h"
#include "parallel.h"
#include "sphere_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace raylab::texgen {

namespace {

const double kPi = 3.14159265358979323846;

// ---- Earth -----------------------------------------------------------------

const std::uint32_t kEarthSeed = 20240601U;

// Raw continent noise at a point: low-frequency fBm, its input displaced by
// another fBm ("domain warping") so coastlines get bays and peninsulas
// instead of round blobs.
double continentNoise(const Vec3& d) {
    const Vec3 q = d * 1.1;
    const Vec3 warp(fbm(q + Vec3(3.1, 0.0, 0.0), kEarthSeed + 1, {3}),
                    fbm(q + Vec3(0.0, 7.7, 0.0), kEarthSeed + 2, {3}),
                    fbm(q + Vec3(0.0, 0.0, 5.3), kEarthSeed + 3, {3}));
    return fbm(q + warp * 0.8, kEarthSeed, {8, 2.03, 0.5});
}

// The value of a field below which FRACTION of the sphere's area lies. Pixels
// near the poles cover less area (cos latitude), so they are weighted less;
// using a quantile instead of a fixed threshold keeps the land share right
// whatever the noise happens to produce.
double areaQuantile(const std::vector<double>& values, int width, int height, double fraction) {
    std::vector<std::pair<double, double>> weighted;
    weighted.reserve(values.size());
    double total = 0;
    for (int y = 0; y < height; ++y) {
        const double weight = std::cos(0.5 * kPi - kPi * (y + 0.5) / height);
        for (int x = 0; x < width; ++x)
            weighted.emplace_back(values[std::size_t(y) * std::size_t(width) + std::size_t(x)],
                                  weight);
        total += weight * width;
    }
    std::sort(weighted.begin(), weighted.end());
    double sum = 0;
    for (const auto& [value, weight] : weighted) {
        sum += weight;
        if (sum >= fraction * total) return value;
    }
    return weighted.back().first;
}

}  // namespace

PlanetTextures earth(int width, int height) {
    std::vector<double> continent(std::size_t(width) * std::size_t(height));
    forEachRow(height, [&](int y) {
        for (int x = 0; x < width; ++x)
            continent[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                continentNoise(equirectPixel(x, y, width, height).normal);
    });
    // About 30% land, like the Earth.
    const double seaLevel = areaQuantile(continent, width, height, 0.70);

    PlanetTextures out{Image(width, height), Image()};
    HeightField relief(width, height);
    const Rgb deepSea = rgb255(10, 30, 82), openSea = rgb255(18, 56, 128),
              shallowSea = rgb255(40, 118, 162);
    const Rgb forest = rgb255(34, 80, 34), grass = rgb255(78, 118, 52),
              savanna = rgb255(140, 138, 76);
    const Rgb desert = rgb255(206, 176, 116), redDesert = rgb255(180, 120, 72),
              tundra = rgb255(116, 112, 90);
    const Rgb rock = rgb255(112, 92, 70), snow = rgb255(236, 238, 242), ice = rgb255(232, 238, 246);
    forEachRow(height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const SpherePoint s = equirectPixel(x, y, width, height);
            const Vec3& d = s.normal;
            const double c =
                continent[std::size_t(y) * std::size_t(width) + std::size_t(x)] - seaLevel;
            const double absLat = std::abs(s.latitude) * 180.0 / kPi;  // degrees
            const double detail =
                fbm(d * 24.0, kEarthSeed + 40, {4});  // small-scale variety everywhere
            Rgb color;
            double elevation =
                0;  // above sea level, in radii: already exaggerated (real mountains are ~1/1000)
            if (c < 0) {
                // Water: shallow shelves along the coasts, darker far out.
                const double depth = -c;
                color = mix(shallowSea, openSea, smoothstep(0.0, 0.06, depth));
                color = mix(color, deepSea, smoothstep(0.06, 0.30, depth));
            } else {
                // Mountains: ridged chains that grow away from the coast.
                const double inland = smoothstep(0.0, 0.12, c);
                const double ridges = ridgedFbm(d * 5.0, kEarthSeed + 20, {6, 2.1, 0.5});
                const double mountain = inland * smoothstep(0.45, 0.85, ridges);
                elevation = 0.25 * c + 0.05 * mountain + 0.006 * inland * (0.5 + 0.5 * detail);
                // Climate: deserts in the dry subtropical belts (about 15-35
                // degrees) where a moisture field is low, forest where it is
                // wet, tundra toward the poles.
                const double moisture =
                    fbm(d * 2.6, kEarthSeed + 30, {5}) + 0.25 * (1.0 - smoothstep(0.0, 0.25, c));
                const double subtropic =
                    smoothstep(8.0, 18.0, absLat) * (1.0 - smoothstep(32.0, 42.0, absLat));
                const double dryness = clamp01(subtropic * smoothstep(0.05, -0.2, moisture) * 1.3 +
                                               smoothstep(0.05, 0.35, -moisture) * 0.5);
                color = mix(grass, forest, smoothstep(-0.05, 0.2, moisture));
                color = mix(color, savanna, smoothstep(0.1, 0.45, dryness));
                color = mix(color, mix(desert, redDesert, smoothstep(-0.2, 0.3, detail)),
                            smoothstep(0.45, 0.8, dryness));
                color = mix(color, tundra, smoothstep(50.0, 62.0, absLat + 6.0 * detail));
                color = mix(color, rock, smoothstep(0.2, 0.6, mountain));
                // Snow only on the highest crests, lower toward the poles.
                color = mix(color, snow, smoothstep(0.88, 0.98, ridges * inland + 0.003 * absLat));
                color = color * (1.0 + 0.10 * detail);
            }
            // Ice caps over land and sea, with a ragged edge.
            const double capEdge = 72.0 + 7.0 * fbm(d * 4.0, kEarthSeed + 50, {5});
            const double capIce = smoothstep(capEdge - 2.0, capEdge + 2.0, absLat);
            color = mix(color, ice * (1.0 - 0.04 * detail), capIce);
            setPixel(out.color, x, y, color);
            relief.at(x, y) = elevation;
        }
    });
    out.normal = sphereNormalMap(relief, 1.0);
    return out;
}

// ---- Moon ------------------------------------------------------------------

namespace {

const std::uint32_t kMoonSeed = 19690720U;

struct Crater {
    Vec3 center;      // unit direction
    double radius;    // rim radius, radians of arc
    double cosReach;  // cos of the angle beyond which it has no effect
    bool fresh;       // young craters keep bright ejecta
};

// Maria: the dark, smooth lava plains, mostly on one hemisphere (the near
// side, around +z, facing the viewer at u = 0.5).
double mareAmount(const Vec3& d) {
    const Vec3 q = d * 1.7;
    const Vec3 warp(fbm(q + Vec3(1.3, 0, 0), kMoonSeed + 1, {3}),
                    fbm(q + Vec3(0, 4.1, 0), kMoonSeed + 2, {3}), 0.0);
    const double m = fbm(q + warp * 0.8, kMoonSeed, {5}) + 0.22 * d.z;
    return smoothstep(0.08, 0.30, m);
}

// Craters at uniformly spread directions with a power-law size distribution:
// many small ones, few large ones, as on real surfaces.
std::vector<Crater> makeCraters(int count, double minRadius, double maxRadius) {
    std::vector<Crater> craters;
    for (int i = 0; i < count; ++i) {
        const double z = 2.0 * cellRandom(i, 0, 0, kMoonSeed, 0) - 1.0;
        const double phi = 2.0 * kPi * cellRandom(i, 0, 0, kMoonSeed, 1);
        const double r = std::sqrt(1.0 - z * z);
        Crater c;
        c.center = Vec3(r * std::cos(phi), r * std::sin(phi), z);
        c.radius = minRadius * std::pow(maxRadius / minRadius,
                                        std::pow(cellRandom(i, 0, 0, kMoonSeed, 2), 2.5));
        c.cosReach = std::cos(std::min(kPi, c.radius * 2.5));
        c.fresh = cellRandom(i, 0, 0, kMoonSeed, 3) < 0.18;
        // The maria are younger than the highlands: most craters there were
        // drowned by the lava.
        if (mareAmount(c.center) > 0.5 && cellRandom(i, 0, 0, kMoonSeed, 4) < 0.7) continue;
        craters.push_back(c);
    }
    return craters;
}

// Height of a crater at T rim radii from its centre, in rim radii: a parabolic
// bowl below the surroundings, a sharp raised rim at T = 1, and an ejecta
// blanket that falls off outside.
double craterProfile(double t) {
    const double depth = 0.22, rim = 0.07;
    if (t < 1.0) return -depth + (depth + rim) * t * t;
    return rim * std::exp(-(t - 1.0) * 4.0);
}

}  // namespace

PlanetTextures moon(int width, int height) {
    const double pixelArc = 2.0 * kPi / width;
    const std::vector<Crater> craters = makeCraters(900, 1.5 * pixelArc, 0.28);
    PlanetTextures out{Image(width, height), Image()};
    HeightField relief(width, height);
    const Rgb highland = rgb255(168, 166, 160), mare = rgb255(82, 84, 88);
    forEachRow(height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const Vec3 d = equirectPixel(x, y, width, height).normal;
            const double mareT = mareAmount(d);
            const double grain = fbm(d * 16.0, kMoonSeed + 10, {5});
            double h = 0.004 * fbm(d * 6.0, kMoonSeed + 11, {6}) - 0.004 * mareT;
            double brightness = 0.0;
            for (const Crater& c : craters) {
                const double cosAngle = glm::dot(d, c.center);
                if (cosAngle < c.cosReach) continue;
                const double t = std::acos(std::min(1.0, cosAngle)) / c.radius;
                h += c.radius * craterProfile(t);
                // Rims catch light and show fresher rock; floors are filled
                // with darker, older dust; young craters keep bright ejecta.
                brightness += 0.05 * std::exp(-(t - 1.0) * (t - 1.0) * 40.0);
                if (t < 0.85) brightness -= 0.06;
                if (c.fresh) brightness += 0.12 * std::exp(-std::max(0.0, t - 0.9) * 2.2);
            }
            Rgb color =
                mix(highland, mare, mareT) * (1.0 + 0.08 * grain + std::min(brightness, 0.25));
            setPixel(out.color, x, y, color);
            relief.at(x, y) = h;
        }
    });
    out.normal = sphereNormalMap(relief, 1.0);
    return out;
}

// ---- Sun ---------------------------------------------------------------------

namespace {

// The photosphere at one point: granules (convection cells, bright centres,
// darker lanes where two cells meet: F2 - F1 small) over larger, slower
// brightness variations (supergranulation).
Rgb photosphere(const Vec3& d) {
    const std::uint32_t seed = 15U;
    const Rgb lane = rgb255(242, 140, 30), granule = rgb255(255, 222, 120),
              hot = rgb255(255, 246, 200);
    const Vec3 warp(fbm(d * 6.0, seed + 1, {3}), fbm(d * 6.0, seed + 2, {3}),
                    fbm(d * 6.0, seed + 3, {3}));
    const CellDistances cell = cellular(d * 7.0 + warp * 0.4, seed);
    const double lanes =
        smoothstep(0.0, 0.22, cell.f2 - cell.f1) * (1.0 - 0.35 * smoothstep(0.2, 0.9, cell.f1));
    const double large = 0.5 + 0.5 * fbm(d * 3.0, seed + 4, {4});
    const Rgb color = mix(lane, granule, lanes * (0.7 + 0.3 * large));
    return mix(color, hot, smoothstep(0.6, 1.0, lanes * large));
}

}  // namespace

Image sun(int width, int height) {
    Image out(width, height);
    forEachRow(height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            // Lanes are about a pixel wide: 2 x 2 samples per pixel keep
            // them from breaking into staircases.
            Rgb sum;
            for (int sy = 0; sy < 2; ++sy)
                for (int sx = 0; sx < 2; ++sx)
                    sum = sum + photosphere(equirectPoint(x + 0.25 + 0.5 * sx, y + 0.25 + 0.5 * sy,
                                                          width, height)
                                                .normal);
            setPixel(out, x, y, sum * 0.25);
        }
    });
    return out;
}

}  // namespace raylab::texgen
