#pragma once
// An off-screen render target, RGBA8 (or RGBA32F where grading must see NaN
// and Inf, which 8-bit colour would hide). Every frame, windowed or headless, is
// drawn into one of these, so both paths produce the same pixels; the window
// only copies it to the screen.
//
// A check's target (Rgba32FWithTodoMarks) also has a second, 8-bit
// attachment: the TODO marks. A lab
// compiled with RAYLAB_TODO_MARK writes 1 there for every pixel whose
// computation reached a TODO stub (lab_todo.glsl), so the checks tell
// unfinished work from a magenta object by what the shader did, not by colour.
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
    void bind() const;  // as the draw target, with the viewport set
    // Clears the colour to (R, G, B, 1), the depth to 1 and the TODO marks to 0.
    void clear(float r, float g, float b) const;
    Image read() const;                     // top row first
    std::vector<float> readFloats() const;  // RGBA, top row first
    PixelFormat format() const { return format_; }
    void blitToScreen(int screenWidth, int screenHeight) const;
    bool hasTodoMarks() const { return todo_ != 0; }
    // Pixels of the last frame that reached a TODO stub; -1 without marks.
    long countTodoMarks() const;

private:
    int width_, height_;
    PixelFormat format_;
    GLuint fbo_ = 0;
    GLuint color_ = 0;
    GLuint todo_ = 0;   // R8 TODO marks, Rgba32FWithTodoMarks only
    GLuint depth_ = 0;  // 24-bit depth renderbuffer
};

}  // namespace raylab
