#pragma once
// The light buffer (scene/light_buffer.h) on the GPU: two buffer textures
// that light_buffer.glsl reads with texelFetch.
//   uLightCells (RGBA32I): texel c = (first, count) of cell c's spheres, then of its triangles
//   uLightItems (R32I):    the lists, sphere and triangle indices
// Needs a current GL context. (Students need not read this file.)
#include "buffer_texture_pair.h"
#include "light_buffer.h"

namespace raylab {

class LightBufferBuffers {
public:
    explicit LightBufferBuffers(const LightBuffer& buffer);

    // Binds the cell texture to CELLUNIT and the list texture to ITEMUNIT.
    void bind(int cellUnit, int itemUnit) const { textures_.bind(cellUnit, itemUnit); }
    // Sets the uniforms light_buffer.glsl reads besides the textures.
    void setUniforms(GLuint program) const;

private:
    BufferTexturePair textures_;
    int resolution_ = 0;
    int everyObjectCell_ = 0;
    float reach_ = 0.0f;
};

}  // namespace raylab
