#pragma once
// Tangent-space normal maps from equirectangular height fields.
//
// Encoding (the convention of every *_normal.png; see assets/LICENSES.md):
//   R = component along +u (east),
//   G = component along +v, where +v points toward the TOP row of the image
//       (north; GLSL's +v once Texture2D has stored the rows bottom first),
//   B = component along the outward surface normal,
// each stored as n * 0.5 + 0.5, so flat ground is (128, 128, 255). The frame
// (east, north, normal) is right-handed, the usual OpenGL ("+Y up") layout.
#include "image.h"

#include <cstddef>
#include <vector>

namespace raylab::texgen {

// Heights for the pixel centres of an equirectangular image, rows top to
// bottom like Image. The unit is the sphere's radius.
struct HeightField {
    int width = 0, height = 0;
    std::vector<double> h;

    HeightField(int w, int hgt)
        : width(w), height(hgt), h(std::size_t(w) * std::size_t(hgt), 0.0) {}
    double& at(int x, int y) { return h[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    double at(int x, int y) const {
        return h[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

// Slopes are measured on the unit sphere (height per radian of arc along the
// surface) and multiplied by EXAGGERATION: true relief is far too small to
// see at planet scale. WIDTH must be even (the neighbour of a polar row across
// the pole is half a turn away).
Image sphereNormalMap(const HeightField& field, double exaggeration);

}  // namespace raylab::texgen
