#include "texture.h"

#include "error.h"
#include "image.h"
#include "paths.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace raylab {

namespace {
std::vector<std::uint8_t> bottomRowFirst(const Image& image) {
    std::vector<std::uint8_t> rows(image.rgba.size());
    const std::size_t row = std::size_t(image.width) * 4;
    for (int y = 0; y < image.height; ++y)
        std::memcpy(&rows[std::size_t(image.height - 1 - y) * row], image.pixel(0, y), row);
    return rows;
}
}  // namespace

TextureArray::TextureArray(const std::vector<std::filesystem::path>& files) {
    std::vector<Image> images;
    for (const auto& f : files) {
        images.push_back(loadPng(f));
        width_ = std::max(width_, images.back().width);
        height_ = std::max(height_, images.back().height);
    }
    GLint maxSize = 0, maxLayers = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    for (std::size_t i = 0; i < images.size(); ++i)
        if (images[i].width > maxSize || images[i].height > maxSize)
            throw Error("texture " + displayPath(files[i]) + " is " +
                        std::to_string(images[i].width) + "x" + std::to_string(images[i].height) +
                        ": this OpenGL takes at most " + std::to_string(maxSize) +
                        " pixels per side");
    if (int(images.size()) > maxLayers)
        throw Error(std::to_string(images.size()) + " textures, but this OpenGL takes at most " +
                    std::to_string(maxLayers) + " in an array");
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    int layers = std::max(1, int(images.size()));
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, std::max(1, width_), std::max(1, height_),
                 layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    for (std::size_t i = 0; i < images.size(); ++i) {
        std::vector<std::uint8_t> rows =
            bottomRowFirst(resampledBilinear(images[i], width_, height_));
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(i), width_, height_, 1, GL_RGBA,
                        GL_UNSIGNED_BYTE, rows.data());
    }
    // No mipmaps: the tracer samples at level 0 (texture derivatives are
    // undefined inside its data-dependent loop).
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    if (GLenum e = glGetError(); e != GL_NO_ERROR) {
        glDeleteTextures(1, &id_);
        throw Error("cannot upload the scene's textures (OpenGL error " + std::to_string(e) +
                    ", out of memory?)");
    }
}

TextureArray::~TextureArray() { glDeleteTextures(1, &id_); }

void TextureArray::bind(int unit) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
}

Texture2D::Texture2D(const std::filesystem::path& file) {
    Image image = loadPng(file);
    width_ = image.width;
    height_ = image.height;
    std::vector<std::uint8_t> rows = bottomRowFirst(image);
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 rows.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
}

Texture2D::~Texture2D() { glDeleteTextures(1, &id_); }

void Texture2D::bind(int unit) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, id_);
}

CubeMap::CubeMap(const CubeFaces& faces) {
    std::array<Image, 6> images;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        images[i] = loadPng(faces[i]);
        const Image& img = images[i];
        if (img.width != img.height)
            throw Error("sky box face " + displayPath(faces[i]) + " is " +
                        std::to_string(img.width) + "x" + std::to_string(img.height) +
                        ", faces must be square");
        if (i > 0 && img.width != images[0].width)
            throw Error("sky box face " + displayPath(faces[i]) + " is " +
                        std::to_string(img.width) + " pixels wide, " + displayPath(faces[0]) +
                        " is " + std::to_string(images[0].width) + ": faces must have one size");
    }
    size_ = images[0].width;
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_CUBE_MAP, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t i = 0; i < images.size(); ++i)
        glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), 0, GL_RGBA8, size_, size_, 0,
                     GL_RGBA, GL_UNSIGNED_BYTE, images[i].rgba.data());
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
    // Filter across face edges (context state, core since GL 3.2; without it
    // some GPUs show the cube's edges in the sky).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

CubeMap::~CubeMap() { glDeleteTextures(1, &id_); }

void CubeMap::bind(int unit) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_CUBE_MAP, id_);
}

}  // namespace raylab
