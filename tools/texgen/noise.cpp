#include "noise.h"

#include <cmath>

namespace raylab::texgen {

std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

namespace {
// The lattice point folded into one word before mixing. Large odd
// multipliers make (1, 2, 0) and (2, 1, 0) differ; the seed is mixed on its
// own first, so that seeds s and s + 1 do not just shift the lattice.
std::uint32_t latticeWord(int x, int y, int z, std::uint32_t mixedSeed) {
    return static_cast<std::uint32_t>(x) * 0x8da6b343U +
           static_cast<std::uint32_t>(y) * 0xd8163841U +
           static_cast<std::uint32_t>(z) * 0xcb1ab31fU + mixedSeed;
}
}  // namespace

std::uint32_t hashCell(int x, int y, int z, std::uint32_t seed) {
    return hash32(latticeWord(x, y, z, hash32(seed)));
}

double unitFloat(std::uint32_t h) { return static_cast<double>(h) / 4294967296.0; }

double hashRandom(std::uint32_t h, int k) {
    return unitFloat(hash32(h ^ (0x9e3779b9U * static_cast<std::uint32_t>(k + 1))));
}

double cellRandom(int x, int y, int z, std::uint32_t seed, int k) {
    return hashRandom(hashCell(x, y, z, seed), k);
}

namespace {

// Quintic fade: zero first and second derivatives at the lattice points, so
// the noise has no creases there (the cubic one shows a faint grid in the
// normal maps, which differentiate the height).
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

int wrap(int i, int period) {
    if (period <= 0) return i;
    int m = i % period;
    return m < 0 ? m + period : m;
}

// Gradients: the 12 directions to the edges of a cube (Perlin's improved
// noise), so no axis is favoured; four of them repeated to make 16, so that
// the top four bits of the hash pick one with a table look-up instead of a
// branch that the CPU cannot predict (this loop is where the time goes).
const double kGradients[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 1}, {0, -1, -1},
};

double gradientDot(std::uint32_t h, double x, double y, double z) {
    const double* g = kGradients[h >> 28];
    return g[0] * x + g[1] * y + g[2] * z;
}

}  // namespace

double gradientNoise(const Vec3& p, std::uint32_t seed, Period period) {
    const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
    const double tx = p.x - fx, ty = p.y - fy, tz = p.z - fz;
    const std::uint32_t mixedSeed =
        hash32(seed);  // once, not per corner: this loop is the hot spot
    double corner[2][2][2];
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                std::uint32_t h =
                    hash32(latticeWord(wrap(ix + dx, period.x), wrap(iy + dy, period.y),
                                       wrap(iz + dz, period.z), mixedSeed));
                corner[dz][dy][dx] = gradientDot(h, tx - dx, ty - dy, tz - dz);
            }
    const double u = fade(tx), v = fade(ty), w = fade(tz);
    auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
    double y0 = lerp(lerp(corner[0][0][0], corner[0][0][1], u),
                     lerp(corner[0][1][0], corner[0][1][1], u), v);
    double y1 = lerp(lerp(corner[1][0][0], corner[1][0][1], u),
                     lerp(corner[1][1][0], corner[1][1][1], u), v);
    return lerp(y0, y1, w);
}

double fbm(const Vec3& p, std::uint32_t seed, FbmShape shape) {
    double sum = 0, amplitude = 1, norm = 0, frequency = 1;
    for (int i = 0; i < shape.octaves; ++i) {
        // A different seed and offset per octave: otherwise every octave is
        // zero at the origin and the layers' features stack up there.
        const Vec3 shift(17.13 * i, -9.71 * i, 5.37 * i);
        sum += amplitude *
               gradientNoise(p * frequency + shift, seed + static_cast<std::uint32_t>(i) * 101U);
        norm += amplitude;
        amplitude *= shape.gain;
        frequency *= shape.lacunarity;
    }
    return sum / norm;
}

double ridgedFbm(const Vec3& p, std::uint32_t seed, FbmShape shape) {
    double sum = 0, amplitude = 1, norm = 0, frequency = 1, weight = 1;
    for (int i = 0; i < shape.octaves; ++i) {
        const Vec3 shift(-3.31 * i, 11.7 * i, 7.9 * i);
        double n = 1.0 - std::abs(gradientNoise(p * frequency + shift,
                                                seed + static_cast<std::uint32_t>(i) * 131U));
        n *= n;
        sum += amplitude * n * weight;
        norm += amplitude;
        weight = std::min(1.0, n * 1.5);
        amplitude *= shape.gain;
        frequency *= shape.lacunarity;
    }
    return sum / norm;
}

double tileableFbm(double u, double v, int base, std::uint32_t seed, int octaves, double gain) {
    double sum = 0, amplitude = 1, norm = 0;
    int cells = base;
    for (int i = 0; i < octaves; ++i) {
        // z is fixed off the lattice (gradient noise is zero on whole-number planes).
        const Vec3 p(u * cells + 0.37 * i, v * cells + 0.61 * i, 0.5 + 0.23 * i);
        sum += amplitude * gradientNoise(p, seed + static_cast<std::uint32_t>(i) * 101U,
                                         Period{cells, cells, 0});
        norm += amplitude;
        amplitude *= gain;
        cells *= 2;
    }
    return sum / norm;
}

CellDistances cellular(const Vec3& p, std::uint32_t seed) {
    const int ix = static_cast<int>(std::floor(p.x)), iy = static_cast<int>(std::floor(p.y)),
              iz = static_cast<int>(std::floor(p.z));
    CellDistances d{1e9, 1e9};
    // Each cell's point lies inside its cell, so the 3x3x3 block around P's
    // cell almost always holds the two nearest; the rare misses (a point two
    // cells away that is nearer) only shift a lane by a fraction of a pixel.
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int cx = ix + dx, cy = iy + dy, cz = iz + dz;
                const std::uint32_t h = hashCell(cx, cy, cz, seed);
                Vec3 point(cx + hashRandom(h, 0), cy + hashRandom(h, 1), cz + hashRandom(h, 2));
                Vec3 diff = point - p;
                double dist = std::sqrt(diff.x * diff.x + diff.y * diff.y + diff.z * diff.z);
                if (dist < d.f1) {
                    d.f2 = d.f1;
                    d.f1 = dist;
                } else if (dist < d.f2) {
                    d.f2 = dist;
                }
            }
    return d;
}

}  // namespace raylab::texgen
