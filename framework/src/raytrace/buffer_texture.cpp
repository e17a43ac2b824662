#include "buffer_texture.h"

namespace raylab {

BufferTexture::BufferTexture() {
    glGenBuffers(1, &buffer_);
    glGenTextures(1, &texture_);
}

BufferTexture::~BufferTexture() {
    glDeleteTextures(1, &texture_);
    glDeleteBuffers(1, &buffer_);
}

void BufferTexture::fill(GLenum format, const void* data, std::size_t bytes) {
    glBindBuffer(GL_TEXTURE_BUFFER, buffer_);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, texture_);
    glTexBuffer(GL_TEXTURE_BUFFER, format, buffer_);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void BufferTexture::bind(int unit) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_BUFFER, texture_);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace raylab
