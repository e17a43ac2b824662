#pragma once
// The eye's cells (scene/eye_cells.h) on the GPU, for the eye-cells variant
// of the BVH walk (variants/eye-cells/08-full/test_spheres.glsl):
//   uEyeCells (RG32I): texel c = (first, count) of cell c's spheres in uBvhItems
// The lists go after the tree's own items in the BVH's item texture, so the
// walk reads a cell's list as it reads a leaf. Rebuilt when the eye moves.
// Needs a current GL context. (Students need not read this file.)
#include "buffer_texture.h"
#include "bvh_buffers.h"
#include "eye_cells.h"

namespace raylab {

class EyeCellBuffers {
public:
    // Builds the cells of SCENE's spheres around EYE unless they are
    // already around it, and uploads them, their lists into BVH.
    void update(const Scene& scene, glm::vec3 eye, BvhBuffers& bvh);

    // Binds the cell texture to UNIT and sets the uniforms the walk reads.
    void bind(GLuint program, int unit) const;

private:
    CellCube cube_{kEyeCellResolution};  // the cells' geometry, the same for every eye
    BufferTexture cells_;
    bool built_ = false;
    glm::vec3 eye_{0.0f};
};

}  // namespace raylab
