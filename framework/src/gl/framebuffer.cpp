#include "framebuffer.h"

#include "error.h"

#include <cstring>
#include <string>

namespace raylab {

Framebuffer::Framebuffer(int width, int height, PixelFormat format)
    : width_(width), height_(height), format_(format) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
        throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is not supported (at most " + std::to_string(maxSize) + " per side)");
    glGenTextures(1, &color_);
    glBindTexture(GL_TEXTURE_2D, color_);
    if (format != PixelFormat::Rgba8)
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    else
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
    if (format == PixelFormat::Rgba32FWithTodoMarks) {
        glGenTextures(1, &todo_);
        glBindTexture(GL_TEXTURE_2D, todo_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, width, height, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, todo_, 0);
        const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glDrawBuffers(2, both);
    }
    // A depth buffer for the tracks that rasterise meshes (the ray tracer
    // draws one canvas and leaves the depth test off).
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &fbo_);
        glDeleteRenderbuffers(1, &depth_);
        glDeleteTextures(1, &color_);
        glDeleteTextures(1, &todo_);
        throw Error("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                    " framebuffer (status 0x" + std::to_string(status) + ")");
    }
}

Framebuffer::~Framebuffer() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &depth_);
    glDeleteTextures(1, &color_);
    glDeleteTextures(1, &todo_);
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
}

void Framebuffer::clear(float r, float g, float b) const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    const GLfloat colour[] = {r, g, b, 1.0f}, zero[] = {0, 0, 0, 0}, depth = 1.0f;
    glClearBufferfv(GL_COLOR, 0, colour);
    if (todo_) glClearBufferfv(GL_COLOR, 1, zero);
    glClearBufferfv(GL_DEPTH, 0, &depth);
}

long Framebuffer::countTodoMarks() const {
    if (!todo_) return -1;
    std::vector<std::uint8_t> marks(std::size_t(width_) * std::size_t(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RED, GL_UNSIGNED_BYTE, marks.data());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    long n = 0;
    for (std::uint8_t m : marks) n += m > 127;
    return n;
}

Image Framebuffer::read() const {
    Image image(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bottomUp(image.rgba.size());
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    const std::size_t row = std::size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)
        std::memcpy(image.pixel(0, y), bottomUp.data() + std::size_t(height_ - 1 - y) * row, row);
    return image;
}

std::vector<float> Framebuffer::readFloats() const {
    std::vector<float> bottomUp(std::size_t(width_) * std::size_t(height_) * 4),
        rows(bottomUp.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, bottomUp.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    const std::size_t row = std::size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)
        std::memcpy(&rows[std::size_t(y) * row], &bottomUp[std::size_t(height_ - 1 - y) * row],
                    row * sizeof(float));
    return rows;
}

void Framebuffer::blitToScreen(int screenWidth, int screenHeight) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    // Scaled up (a frame drawn with fewer pixels while the camera moves):
    // smooth rather than blocky.
    const bool sameSize = screenWidth == width_ && screenHeight == height_;
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, screenWidth, screenHeight, GL_COLOR_BUFFER_BIT,
                      sameSize ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace raylab
