#pragma once
// A starry sky box: sparse stars of different brightness and tint over a faint
// coloured nebula. The colour is a function of the view direction only, so
// the six faces (laid out as in cube_map.h) meet without seams and no star is
// cut at a face edge.
#include "color.h"
#include "image.h"
#include "noise.h"

#include <array>

namespace raylab::texgen {

// The sky seen in unit direction D.
Rgb skyColor(const Vec3& d);

// The six SIZE x SIZE faces, in GL_TEXTURE_CUBE_MAP_POSITIVE_X + i order.
std::array<Image, 6> skyBox(int size);

}  // namespace raylab::texgen
