#include "normal_map.h"

#include "color.h"
#include "error.h"

#include <algorithm>
#include <cmath>

namespace raylab::texgen {

Image sphereNormalMap(const HeightField& field, double exaggeration) {
    const int w = field.width, hgt = field.height;
    if (w % 2 != 0) throw Error("sphereNormalMap: the width must be even");
    const double pi = 3.14159265358979323846;
    const double dLon = 2.0 * pi / w, dLat = pi / hgt;
    // One column spans dLon * cos(latitude) radians of arc, which goes to zero
    // at the poles. The polar rows' centres sit half a row from the pole, so
    // cos(latitude) never reaches 0 there, but a height field that is not a
    // smooth function on the sphere (a test ramp in u, say) would blow up;
    // below one row's worth of arc the east slope is taken as if at that arc.
    const double minCos = std::sin(dLat);
    // Row -1 (beyond the top) is row 0 half a turn away, across the pole; the
    // same below the bottom. This keeps the north slope right at the poles.
    auto sample = [&](int x, int y) {
        if (y < 0) {
            y = -1 - y;
            x += w / 2;
        } else if (y >= hgt) {
            y = 2 * hgt - 1 - y;
            x += w / 2;
        }
        x = ((x % w) + w) % w;  // longitude wraps: column -1 is the last one
        return field.at(x, y);
    };
    Image out(w, hgt);
    for (int y = 0; y < hgt; ++y) {
        const double latitude = 0.5 * pi - pi * (y + 0.5) / hgt;
        const double eastArc = dLon * std::max(std::cos(latitude), minCos);
        for (int x = 0; x < w; ++x) {
            const double dEast = (sample(x + 1, y) - sample(x - 1, y)) / (2.0 * eastArc);
            const double dNorth =
                (sample(x, y - 1) - sample(x, y + 1)) / (2.0 * dLat);  // row y-1 is further north
            // The surface r = 1 + h tilts against its slope: a height rising
            // eastward turns the normal toward the west.
            double nx = -exaggeration * dEast, ny = -exaggeration * dNorth, nz = 1.0;
            const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
            setPixel(out, x, y,
                     Rgb{nx / len * 0.5 + 0.5, ny / len * 0.5 + 0.5, nz / len * 0.5 + 0.5});
        }
    }
    return out;
}

}  // namespace raylab::texgen
