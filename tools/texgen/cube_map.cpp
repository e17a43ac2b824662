#include "cube_map.h"

#include <glm/geometric.hpp>

namespace raylab::texgen {

Vec3 cubeFaceDirection(int face, int x, int y, int size) {
    const double s = 2.0 * (x + 0.5) / size - 1.0;
    const double t = 2.0 * (y + 0.5) / size - 1.0;
    Vec3 d;
    switch (face) {
    case 0: d = Vec3(1.0, -t, -s); break;
    case 1: d = Vec3(-1.0, -t, s); break;
    case 2: d = Vec3(s, 1.0, t); break;
    case 3: d = Vec3(s, -1.0, -t); break;
    case 4: d = Vec3(s, -t, 1.0); break;
    default: d = Vec3(-s, -t, -1.0); break;
    }
    return glm::normalize(d);
}

}  // namespace raylab::texgen
