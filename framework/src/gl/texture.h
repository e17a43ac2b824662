#pragma once
// Textures loaded from image files through SDL2_image: 2D textures and sky
// boxes (a cube map made of six faces).
#include "gl.h"

#include <array>
#include <filesystem>
#include <vector>

namespace raylab {

class Texture2D {
public:
    // RGBA8, mipmapped, repeating. Rows are stored bottom first, so that in
    // GLSL texture(t, vec2(u, v)) with v = 0 at the bottom of the picture
    // shows the picture upright. Throws Error naming the file.
    explicit Texture2D(const std::filesystem::path& file);
    ~Texture2D();
    Texture2D(const Texture2D&) = delete;
    Texture2D& operator=(const Texture2D&) = delete;

    GLuint id() const { return id_; }
    int width() const { return width_; }
    int height() const { return height_; }
    void bind(int unit) const;

private:
    GLuint id_ = 0;
    int width_ = 0, height_ = 0;
};

// Several pictures as the layers of one GL_TEXTURE_2D_ARRAY, so that a
// shader can pick a material's texture by number (an array of sampler2D
// could only be indexed by constants in GLSL 3.30). Every picture is
// resampled to the size of the largest; texture coordinates are 0..1 across
// a picture whatever its size, so this changes sharpness, not placement.
// Rows are stored bottom first, as in Texture2D. Throws Error naming the file.
class TextureArray {
public:
    explicit TextureArray(const std::vector<std::filesystem::path>& files);
    ~TextureArray();
    TextureArray(const TextureArray&) = delete;
    TextureArray& operator=(const TextureArray&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    void bind(int unit) const;

private:
    GLuint id_ = 0;
    int width_ = 0, height_ = 0;
};

// The six faces of a sky box, in OpenGL's order: +x, -x, +y, -y, +z, -z.
using CubeFaces = std::array<std::filesystem::path, 6>;

class CubeMap {
public:
    // All faces square and of one size; stored as given (cube maps use the
    // top-left origin, unlike 2D textures). Throws Error naming the file.
    explicit CubeMap(const CubeFaces& faces);
    ~CubeMap();
    CubeMap(const CubeMap&) = delete;
    CubeMap& operator=(const CubeMap&) = delete;

    GLuint id() const { return id_; }
    int size() const { return size_; }
    void bind(int unit) const;

private:
    GLuint id_ = 0;
    int size_ = 0;
};

}  // namespace raylab
