#pragma once
// The BVH (bvh.h) on the GPU: two buffer textures the GLSL traversal reads
// with texelFetch (solution/08-full/find_closest.glsl). Buffer textures, not
// uniform arrays: a few hundred nodes would crowd the uniform limits some
// drivers have (1024 vec4s for a whole fragment shader on NVIDIA).
//   uBvhNodes (RGBA32F): texel 2i = (box.lo, first), texel 2i+1 = (box.hi, count)
//   uBvhItems (R32I):    object ids
// Needs a current GL context. (Students need not read this file.)
#include "bvh.h"
#include "gl.h"

namespace raylab {

class BvhBuffers {
public:
    explicit BvhBuffers(const Bvh& bvh);
    ~BvhBuffers();
    BvhBuffers(const BvhBuffers&) = delete;
    BvhBuffers& operator=(const BvhBuffers&) = delete;

    // Binds the node texture to NODEUNIT and the item texture to ITEMUNIT.
    void bind(int nodeUnit, int itemUnit) const;
    int nodeCount() const { return nodeCount_; }

private:
    GLuint buffers_[2] = {0, 0};
    GLuint textures_[2] = {0, 0};
    int nodeCount_ = 0;
};

}  // namespace raylab
