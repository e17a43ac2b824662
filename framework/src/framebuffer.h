#pragma once
// An off-screen RGBA8 render target. Every frame, windowed or headless, is
// drawn into one of these, so both paths produce the same pixels; the window
// only copies it to the screen.
#include "gl.h"
#include "image.h"

namespace raylab {

class Framebuffer {
public:
    Framebuffer(int width, int height);
    ~Framebuffer();
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    void bind() const;             // as the draw target, with the viewport set
    Image read() const;            // top row first
    void blitToScreen(int screenWidth, int screenHeight) const;

private:
    int width_, height_;
    GLuint fbo_ = 0;
    GLuint color_ = 0;
};

} // namespace raylab
