#pragma once
// The fur track's textures. All tile (GL_REPEAT), since shells repeat the
// pattern across the mesh and fins repeat the strands along an edge.
#include "image.h"

namespace raylab::texgen {

// The coat's colour: a warm brown with darker tabby stripes and a lighter
// belly tone, varied by noise so the coat is not flat.
Image furColor(int size);

// The shells' fur pattern (grey scale in every channel): one hair per texel
// at random, its brightness its height - a shell at layer L keeps a hair
// where the pattern is above about L (alpha = pattern * (1 - layer)), so
// short hairs stop in the lower shells and long ones reach the tips.
Image furPattern(int size);

// The fins' strands seen from the side: rows run from the root (v = 0, the
// bottom of the picture as GL reads it) to the tips. Colour white (the fin
// shader colours it), alpha the coverage of tapering, slightly bent strands.
Image furFin(int width, int height);

}  // namespace raylab::texgen
