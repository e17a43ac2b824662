#pragma once
// Two buffer textures that travel together - a BVH's nodes and items
// (bvh_buffers.h), the mesh triangles' corners and materials
// (scene_mesh_buffers.h), a light buffer's cells and lists
// (light_buffer_buffers.h) - created, filled, bound to two texture units
// and deleted as one. Buffer textures, not uniform arrays: their size is
// limited by memory, not by the few uniform slots some drivers have.
// Needs a current GL context. (Students need not read this file.)
#include "gl.h"

#include <cstddef>

namespace raylab {

class BufferTexturePair {
public:
    BufferTexturePair();
    ~BufferTexturePair();
    BufferTexturePair(const BufferTexturePair&) = delete;
    BufferTexturePair& operator=(const BufferTexturePair&) = delete;

    // Texture WHICH (0 or 1) becomes BYTES of DATA read as FORMAT (an empty
    // buffer texture is not allowed everywhere: callers keep one dummy entry).
    void fill(int which, GLenum format, const void* data, std::size_t bytes);
    // Binds texture 0 to UNIT0 and texture 1 to UNIT1.
    void bind(int unit0, int unit1) const;

private:
    GLuint buffers_[2] = {0, 0};
    GLuint textures_[2] = {0, 0};
};

}  // namespace raylab
