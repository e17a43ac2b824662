#pragma once
// Tileable surface patterns: the right edge continues into the left one and
// the bottom into the top, so they can repeat (GL_REPEAT) over a plane or a
// disc without visible seams. Everything periodic is built from whole
// numbers of periods per tile (tileableFbm, sin(2 pi k u) with integer k).
#include "image.h"

namespace raylab::texgen {

// A 4 x 4 checker of two stone colours with mortar joints and grain.
Image tiles(int size);

// White marble with dark, turbulent veins.
Image marble(int size);

}  // namespace raylab::texgen
