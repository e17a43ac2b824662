#pragma once
// CPU copies of a scene's pictures for the reference tracer, holding exactly
// what framework/src/gl/texture.cpp gives the GPU and sampled the way the GPU
// samples them (textureLod(..., 0.0): level 0, GL_LINEAR, no sRGB):
//  - the texture array: every picture resampled (as texture.cpp does) to the
//    largest picture's size, rows stored bottom first (v = 0 at the bottom
//    of the picture), GL_REPEAT in u and v;
//  - the sky box: a cube map, faces stored as given (t = 0 at the top row),
//    face and (s, t) chosen as in the OpenGL specification.
// Needs no OpenGL context. Pictures are read with loadPng (image.h), the
// framework's loader.
#include "image.h"

#include <glm/glm.hpp>

#include <array>
#include <filesystem>
#include <vector>

namespace raylab::reference {

class TextureLayers {
public:
    // Throws Error naming a picture that cannot be read.
    explicit TextureLayers(const std::vector<std::filesystem::path>& files);

    // textureLod(uTextures, vec3(uv, layer), 0.0): bilinear, texel centres
    // at (i + 0.5) / size, repeating. RGBA in 0..1.
    glm::dvec4 sample(int layer, const glm::dvec2& uv) const;

    int width() const { return width_; }
    int height() const { return height_; }
    int layers() const { return int(layers_.size()); }

private:
    int width_ = 0, height_ = 0;
    std::vector<Image>
        layers_;  // each width_ x height_, row 0 = the picture's BOTTOM row (GL row 0)
};

class SkyCube {
public:
    // Faces +x, -x, +y, -y, +z, -z; square and of one size (else Error, as CubeMap).
    explicit SkyCube(const std::array<std::filesystem::path, 6>& faces);

    // textureLod(uSky, dir, 0.0): face by the major axis, bilinear on it.
    // The GPU filters across face edges (GL_TEXTURE_CUBE_MAP_SEAMLESS); here
    // a texel beyond a face's edge is taken from the neighbouring face by
    // projecting its centre's direction onto the cube again - exact along an
    // edge, an approximation in the three-face corners (where the
    // specification averages three texels). RGBA in 0..1.
    glm::dvec4 sample(const glm::dvec3& dir) const;

    int size() const { return size_; }

private:
    glm::dvec4 texel(int face, int i,
                     int j) const;  // i along s, j along t, may lie outside the face
    int size_ = 0;
    std::array<Image, 6> faces_;  // row 0 = t = 0
};

}  // namespace raylab::reference
