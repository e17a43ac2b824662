#pragma once
// An off-screen render target, RGBA8 (or RGBA32F where grading must see NaN
// and Inf, which 8-bit colour would hide). Every frame, windowed or headless, is
// drawn into one of these, so both paths produce the same pixels; the window
// only copies it to the screen.
#include "gl.h"
#include "image.h"
#include "pixel_format.h"

#include <vector>

namespace raylab {

class Framebuffer {
public:
    Framebuffer(int width, int height, PixelFormat format = PixelFormat::Rgba8);
    ~Framebuffer();
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    void bind() const;                      // as the draw target, with the viewport set
    Image read() const;                     // top row first
    std::vector<float> readFloats() const;  // RGBA, top row first
    PixelFormat format() const { return format_; }
    void blitToScreen(int screenWidth, int screenHeight) const;

private:
    int width_, height_;
    PixelFormat format_;
    GLuint fbo_ = 0;
    GLuint color_ = 0;
    GLuint depth_ = 0;  // 24-bit depth renderbuffer
};

}  // namespace raylab
