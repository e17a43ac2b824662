#pragma once
// The scene's mesh triangles on the GPU (framework/shaders/scene_meshes.glsl):
//   uMeshCorners (RGBA32F): per triangle 6 texels, (corner k, u_k) for k = 0..2
//                           then (normal k, v_k)
//   uMeshMaterials (R32I):  per triangle, its mesh's material
// Buffer textures: a mesh is limited by memory, not by uniform slots.
// Needs a current GL context. (Students need not read this file.)
#include "buffer_texture_pair.h"
#include "scene.h"

namespace raylab {

class SceneMeshBuffers {
public:
    // Throws Error when the triangles exceed the driver's buffer texture size.
    explicit SceneMeshBuffers(const Scene& scene);

    void bind(int cornerUnit, int materialUnit) const { textures_.bind(cornerUnit, materialUnit); }

private:
    BufferTexturePair textures_;
};

}  // namespace raylab
