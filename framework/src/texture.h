#pragma once
// Textures loaded from image files through SDL2_image: 2D textures and sky
// boxes (a cube map made of six faces).
#include "gl.h"

#include <array>
#include <filesystem>

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

} // namespace raylab
