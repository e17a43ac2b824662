#pragma once
// The equirectangular (longitude/latitude) layout of the planet textures.
//
//   column x: u = (x + 0.5) / width in [0, 1), longitude = 2 pi u - pi, so
//             longitude grows eastward from left to right;
//   row y:    top row = north pole, bottom row = south pole,
//             latitude = pi/2 - pi (y + 0.5) / height.
//
// Texture2D stores rows bottom first, so in GLSL v = 0 is the south pole and
// +v points north. The 3D frame used here to evaluate noise (north pole on
// +y, longitude 0 on +z, east toward +x there) is internal: colours are
// functions of the point on the unit sphere, which is what removes the seam
// at u = 0/1 and the pinch at the poles, and a picture depends only on
// (u, v). Any lookup with the same u, v conventions shows it the same way,
// e.g. solution/06-textures/sphere_uv.glsl:
// u = 0.5 + atan(-d.z, d.x) / (2 pi), v = 0.5 + asin(d.y) / pi.
#include "noise.h"

namespace raylab::texgen {

struct SpherePoint {
    double latitude = 0, longitude = 0;  // radians
    Vec3 normal;                         // the unit direction, also the outward surface normal
    Vec3 east;                           // unit tangent toward +u
    Vec3 north;                          // unit tangent toward the top row; east x north = normal
};

// The point at image position (PX, PY), in pixels from the top-left corner of
// a WIDTH x HEIGHT equirectangular image (for supersampling).
SpherePoint equirectPoint(double px, double py, int width, int height);

// The centre of pixel (x, y).
inline SpherePoint equirectPixel(int x, int y, int width, int height) {
    return equirectPoint(x + 0.5, y + 0.5, width, height);
}

}  // namespace raylab::texgen
