#include "buffer_texture_pair.h"

namespace raylab {

BufferTexturePair::BufferTexturePair() {
    glGenBuffers(2, buffers_);
    glGenTextures(2, textures_);
}

BufferTexturePair::~BufferTexturePair() {
    glDeleteTextures(2, textures_);
    glDeleteBuffers(2, buffers_);
}

void BufferTexturePair::fill(int which, GLenum format, const void* data, std::size_t bytes) {
    glBindBuffer(GL_TEXTURE_BUFFER, buffers_[which]);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, textures_[which]);
    glTexBuffer(GL_TEXTURE_BUFFER, format, buffers_[which]);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void BufferTexturePair::bind(int unit0, int unit1) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit0));
    glBindTexture(GL_TEXTURE_BUFFER, textures_[0]);
    glActiveTexture(GLenum(GL_TEXTURE0 + unit1));
    glBindTexture(GL_TEXTURE_BUFFER, textures_[1]);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace raylab
