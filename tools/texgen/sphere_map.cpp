#include "sphere_map.h"

#include <cmath>

namespace raylab::texgen {

SpherePoint equirectPoint(double px, double py, int width, int height) {
    const double pi = 3.14159265358979323846;
    SpherePoint s;
    s.longitude = 2.0 * pi * px / width - pi;
    s.latitude = 0.5 * pi - pi * py / height;
    const double cl = std::cos(s.latitude), sl = std::sin(s.latitude);
    const double co = std::cos(s.longitude), so = std::sin(s.longitude);
    s.normal = Vec3(cl * so, sl, cl * co);
    // Derivatives of the normal by longitude and latitude, normalised.
    s.east = Vec3(co, 0.0, -so);
    s.north = Vec3(-sl * so, cl, -sl * co);
    return s;
}

}  // namespace raylab::texgen
