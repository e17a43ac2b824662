#include "image_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace raylab {

namespace {

int pixelDiff(const std::uint8_t* p, const std::uint8_t* q) {
    return std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])});
}

// Smallest difference between a's pixel (x, y) and b's pixels around (x, y).
int nearestMatch(const Image& a, const Image& b, int x, int y) {
    int best = 255;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= b.width || ny >= b.height) continue;
            best = std::min(best, pixelDiff(a.pixel(x, y), b.pixel(nx, ny)));
        }
    return best;
}

}  // namespace

ImageDiff compareImages(const Image& a, const Image& b, int channelTolerance) {
    ImageDiff diff;
    if (a.width != b.width || a.height != b.height) {
        diff.sameSize = false;
        diff.badShare = 1.0;
        diff.maxDiff = 255;
        return diff;
    }
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int d = std::max(nearestMatch(a, b, x, y), nearestMatch(b, a, x, y));
            diff.maxDiff = std::max(diff.maxDiff, d);
            if (d > channelTolerance) ++diff.badPixels;
        }
    diff.badShare =
        a.width * a.height > 0 ? double(diff.badPixels) / (double(a.width) * a.height) : 0.0;
    return diff;
}

bool imagesAgree(const ImageDiff& diff, const CompareTolerance& tol) {
    return diff.sameSize && diff.badShare <= tol.maxBadShare;
}

std::string describe(const ImageDiff& diff) {
    if (!diff.sameSize) return "image sizes differ";
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.2f%% of pixels differ (max %d/255)", diff.badShare * 100.0,
                  diff.maxDiff);
    return buf;
}

Image diffHeatMap(const Image& a, const Image& b) {
    Image heat(a.width, a.height);
    if (a.width != b.width || a.height != b.height) return heat;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int d = std::max(nearestMatch(a, b, x, y), nearestMatch(b, a, x, y));
            std::uint8_t* p = heat.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(std::min(255, d * 4));
            p[1] = static_cast<std::uint8_t>(d > 0 ? 32 : 0);
            p[2] = 0;
            p[3] = 255;
        }
    return heat;
}

std::string diagnose(const Image& mine, const Image& expected, int channelTolerance,
                     const DiagnoseContext& context) {
    if (context.nonFinite > 0)
        return std::to_string(context.nonFinite) +
               " pixels are NaN or Inf (the magenta ones): in GLSL, sqrt() or pow() of a "
               "negative number, normalize() of a zero vector and 0/0 give NaN; exp() of a large "
               "number and x/0 give Inf";
    if (mine.width != expected.width || mine.height != expected.height) return "";
    const long all = long(mine.width) * long(mine.height);
    auto percent = [&](long n, long of) {
        const double p = 100.0 * double(n) / double(std::max(1L, of));
        return (p > 0 && p < 0.5 ? std::string("under 1") : std::to_string(int(p + 0.5))) + "%";
    };
    if (context.todoPixels > 0)
        return percent(context.todoPixels, all) +
               " of the image reaches an unfinished TODO (the pixels with magenta stripes)";
    long differing = 0, darker = 0, brighter = 0;
    for (int y = 0; y < mine.height; ++y)
        for (int x = 0; x < mine.width; ++x) {
            const std::uint8_t *m = mine.pixel(x, y), *e = expected.pixel(x, y);
            int sumM = m[0] + m[1] + m[2], sumE = e[0] + e[1] + e[2];
            int diff =
                std::max({std::abs(m[0] - e[0]), std::abs(m[1] - e[1]), std::abs(m[2] - e[2])});
            if (diff <= channelTolerance) continue;
            ++differing;
            darker += sumM < sumE;
            brighter += sumM > sumE;
        }
    // One flat colour where the reference has a picture. Said as a fact, with
    // the colour: it may be the background (nothing drawn) or a surface
    // gone white or black (a weight or normal wrong): a hint does not guess.
    long flat = 0, expectedFlat = 0;
    const std::uint8_t *m0 = mine.pixel(0, 0), *e0 = expected.pixel(0, 0);
    auto near = [&](const std::uint8_t* p, const std::uint8_t* q) {
        return std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])}) <=
               channelTolerance;
    };
    for (int y = 0; y < mine.height; ++y)
        for (int x = 0; x < mine.width; ++x) {
            flat += near(mine.pixel(x, y), m0);
            expectedFlat += near(expected.pixel(x, y), e0);
        }
    if (flat >= all * 99 / 100 && expectedFlat < all * 95 / 100)
        return "the picture is one flat colour, (" + std::to_string(m0[0]) + ", " +
               std::to_string(m0[1]) + ", " + std::to_string(m0[2]) +
               "), where the expected one has a picture";
    if (differing == 0) return "";
    if (darker >= differing * 8 / 10)
        return percent(darker, differing) + " of the differing pixels are too dark" +
               (context.darkerCause.empty() ? "" : " (" + context.darkerCause + ")");
    if (brighter >= differing * 8 / 10)
        return percent(brighter, differing) + " of the differing pixels are too bright" +
               (context.brighterCause.empty() ? "" : " (" + context.brighterCause + ")");
    return "";
}

}  // namespace raylab
