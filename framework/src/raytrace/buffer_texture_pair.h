#pragma once
// Two buffer textures that travel together - a BVH's nodes and items
// (bvh_buffers.h), the mesh triangles' corners and materials
// (scene_mesh_buffers.h), a light buffer's cells and lists
// (light_buffer_buffers.h) - filled and bound as one.
// Needs a current GL context. (Students need not read this file.)
#include "buffer_texture.h"

namespace raylab {

class BufferTexturePair {
public:
    // Texture WHICH (0 or 1) becomes BYTES of DATA read as FORMAT (see BufferTexture::fill).
    void fill(int which, GLenum format, const void* data, std::size_t bytes) {
        textures_[which].fill(format, data, bytes);
    }
    // Binds texture 0 to UNIT0 and texture 1 to UNIT1.
    void bind(int unit0, int unit1) const {
        textures_[0].bind(unit0);
        textures_[1].bind(unit1);
    }

private:
    BufferTexture textures_[2];
};

}  // namespace raylab
