#pragma once
// One buffer texture: a GL buffer read by the shaders with texelFetch, as a
// texture of FORMAT texels (the eye's cells, eye_cell_buffers.h; two of them
// make a BufferTexturePair). Buffer textures, not uniform arrays: their size
// is limited by memory, not by the few uniform slots some drivers have.
// Needs a current GL context. (Students need not read this file.)
#include "gl.h"

#include <cstddef>

namespace raylab {

class BufferTexture {
public:
    BufferTexture();
    ~BufferTexture();
    BufferTexture(const BufferTexture&) = delete;
    BufferTexture& operator=(const BufferTexture&) = delete;

    // The texture becomes BYTES of DATA read as FORMAT (an empty buffer
    // texture is not allowed everywhere: callers keep one dummy entry).
    void fill(GLenum format, const void* data, std::size_t bytes);
    void bind(int unit) const;

private:
    GLuint buffer_ = 0;
    GLuint texture_ = 0;
};

}  // namespace raylab
