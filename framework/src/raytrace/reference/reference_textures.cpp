#include "reference_textures.h"

#include "error.h"
#include "paths.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace raylab::reference {

namespace {

// Rows reversed: GL row 0 is the picture's bottom row (texture.cpp's bottomRowFirst).
Image flippedRows(const Image& image) {
    Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        std::copy(image.pixel(0, y), image.pixel(0, y) + std::size_t(image.width) * 4,
                  out.pixel(0, image.height - 1 - y));
    return out;
}

glm::dvec4 unorm(const std::uint8_t* p) { return glm::dvec4(p[0], p[1], p[2], p[3]) / 255.0; }

int wrap(int i, int size) {
    int m = i % size;
    return m < 0 ? m + size : m;
}

// The OpenGL cube-map face of direction R and its (s, t) in 0..1 (the
// specification's table: major axis ma, then sc and tc per face).
void cubeCoordinates(const glm::dvec3& r, int& face, double& s, double& t) {
    const double ax = std::fabs(r.x), ay = std::fabs(r.y), az = std::fabs(r.z);
    double sc, tc, ma;
    if (ax >= ay && ax >= az) {
        ma = ax;
        if (r.x >= 0.0) {
            face = 0;
            sc = -r.z;
            tc = -r.y;
        } else {
            face = 1;
            sc = r.z;
            tc = -r.y;
        }
    } else if (ay >= az) {
        ma = ay;
        if (r.y >= 0.0) {
            face = 2;
            sc = r.x;
            tc = r.z;
        } else {
            face = 3;
            sc = r.x;
            tc = -r.z;
        }
    } else {
        ma = az;
        if (r.z >= 0.0) {
            face = 4;
            sc = r.x;
            tc = -r.y;
        } else {
            face = 5;
            sc = -r.x;
            tc = -r.y;
        }
    }
    s = 0.5 * (sc / ma + 1.0);
    t = 0.5 * (tc / ma + 1.0);
}

// The direction to the point (sc, tc) of FACE's plane (major axis 1): the
// inverse of the table above.
glm::dvec3 cubeDirection(int face, double sc, double tc) {
    switch (face) {
    case 0: return {1.0, -tc, -sc};
    case 1: return {-1.0, -tc, sc};
    case 2: return {sc, 1.0, tc};
    case 3: return {sc, -1.0, -tc};
    case 4: return {sc, -tc, 1.0};
    default: return {-sc, -tc, -1.0};
    }
}

}  // namespace

TextureLayers::TextureLayers(const std::vector<std::filesystem::path>& files) {
    std::vector<Image> images;
    for (const auto& f : files) {
        images.push_back(loadPng(f));
        width_ = std::max(width_, images.back().width);
        height_ = std::max(height_, images.back().height);
    }
    for (const Image& image : images)
        layers_.push_back(flippedRows(resampledBilinear(image, width_, height_)));
}

glm::dvec4 TextureLayers::sample(int layer, const glm::dvec2& uv) const {
    if (layers_.empty()) return glm::dvec4(0.0);  // no pictures: nothing to read
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return glm::dvec4(0.0);
    const Image& img = layers_[std::size_t(std::clamp(layer, 0, int(layers_.size()) - 1))];
    const double x = uv.x * double(width_) - 0.5, y = uv.y * double(height_) - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double a = x - fx, b = y - fy;
    // Far from the origin (a plane's tiles) reduce first: int overflow.
    const int i0 = wrap(int(std::fmod(fx, double(width_))), width_), i1 = wrap(i0 + 1, width_);
    const int j0 = wrap(int(std::fmod(fy, double(height_))), height_), j1 = wrap(j0 + 1, height_);
    return (1 - a) * (1 - b) * unorm(img.pixel(i0, j0)) + a * (1 - b) * unorm(img.pixel(i1, j0)) +
           (1 - a) * b * unorm(img.pixel(i0, j1)) + a * b * unorm(img.pixel(i1, j1));
}

SkyCube::SkyCube(const std::array<std::filesystem::path, 6>& faces) {
    for (std::size_t i = 0; i < faces.size(); ++i) {
        faces_[i] = loadPng(faces[i]);
        const Image& img = faces_[i];
        if (img.width != img.height)
            throw Error("sky box face " + displayPath(faces[i]) + " is " +
                        std::to_string(img.width) + "x" + std::to_string(img.height) +
                        ", faces must be square");
        if (i > 0 && img.width != faces_[0].width)
            throw Error("sky box face " + displayPath(faces[i]) + " is " +
                        std::to_string(img.width) + " pixels wide, " + displayPath(faces[0]) +
                        " is " + std::to_string(faces_[0].width) + ": faces must have one size");
    }
    size_ = faces_[0].width;
}

glm::dvec4 SkyCube::texel(int face, int i, int j) const {
    if (i < 0 || j < 0 || i >= size_ || j >= size_) {
        // Beyond the edge (seamless filtering): the texel centre's direction,
        // looked up again, lands on the neighbouring face next to the edge.
        const double n = double(size_);
        glm::dvec3 dir = cubeDirection(face, 2.0 * (double(i) + 0.5) / n - 1.0,
                                       2.0 * (double(j) + 0.5) / n - 1.0);
        double s, t;
        cubeCoordinates(dir, face, s, t);
        i = std::clamp(int(std::floor(s * n)), 0, size_ - 1);
        j = std::clamp(int(std::floor(t * n)), 0, size_ - 1);
    }
    return unorm(faces_[std::size_t(face)].pixel(i, j));
}

glm::dvec4 SkyCube::sample(const glm::dvec3& dir) const {
    int face;
    double s, t;
    cubeCoordinates(dir, face, s, t);
    const double x = s * double(size_) - 0.5, y = t * double(size_) - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double a = x - fx, b = y - fy;
    const int i = int(fx), j = int(fy);
    return (1 - a) * (1 - b) * texel(face, i, j) + a * (1 - b) * texel(face, i + 1, j) +
           (1 - a) * b * texel(face, i, j + 1) + a * b * texel(face, i + 1, j + 1);
}

}  // namespace raylab::reference
