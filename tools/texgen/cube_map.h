#pragma once
// The direction seen through each pixel of a cube map face, following the
// OpenGL specification's table "Selection of cube map images" (OpenGL 4.6
// core, section 8.13): for the major axis ma and the face's (sc, tc),
//   s = (sc / |ma| + 1) / 2,  t = (tc / |ma| + 1) / 2,
// and texel row 0 (t near 0) is the first row handed to glTexImage2D, i.e.
// the top row of the PNG as framework/src/gl/texture.cpp uploads it unflipped.
// Inverting the table with s, t in [-1, 1] taken at pixel centres (s grows
// with the column x, t with the row y from the top):
//
//   face 0  +X  (px):  ( 1, -t, -s)      face 1  -X  (nx):  (-1, -t,  s)
//   face 2  +Y  (py):  ( s,  1,  t)      face 3  -Y  (ny):  ( s, -1, -t)
//   face 4  +Z  (pz):  ( s, -t,  1)      face 5  -Z  (nz):  (-s, -t, -1)
//
// Faces are numbered in GL_TEXTURE_CUBE_MAP_POSITIVE_X + i order.
#include "noise.h"

#include <array>

namespace raylab::texgen {

constexpr std::array<const char*, 6> kCubeFaceNames = {"px", "nx", "py", "ny", "pz", "nz"};

// Unit direction through the centre of pixel (x, y) of face FACE (0..5).
Vec3 cubeFaceDirection(int face, int x, int y, int size);

}  // namespace raylab::texgen
