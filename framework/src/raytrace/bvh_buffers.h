#pragma once
// The BVH (bvh.h) on the GPU: two buffer textures the GLSL traversal reads
// with texelFetch (solution/08-full/find_closest.glsl). Buffer textures, not
// uniform arrays: a few hundred nodes would crowd the uniform limits some
// drivers have (1024 vec4s for a whole fragment shader on NVIDIA).
//   uBvhNodes (RGBA32F): texel 2i = (box.lo, first), texel 2i+1 = (box.hi, code),
//                        code = 8 * count + kind for a leaf of count items of one
//                        kind (KIND_SPHERE, KIND_MESH, KIND_TRIANGLE, KIND_DISC), 0 for
//                        an inner node
//   uBvhItems (R32I):    indices into the lists of the leaves' kinds
// Needs a current GL context. (Students need not read this file.)
#include "buffer_texture_pair.h"
#include "bvh.h"

#include <vector>

namespace raylab {

class BvhBuffers {
public:
    explicit BvhBuffers(const Bvh& bvh);

    // Binds the node texture to NODEUNIT and the item texture to ITEMUNIT.
    void bind(int nodeUnit, int itemUnit) const { textures_.bind(nodeUnit, itemUnit); }
    int nodeCount() const { return nodeCount_; }
    // Puts TAIL after the tree's own items (lists that the walk takes as
    // leaves: the eye's cells, eye_cell_buffers.h), replacing any earlier
    // tail; returns where it starts.
    int setItemTail(const std::vector<int>& tail);

private:
    void fillItems(const std::vector<int>& tail);

    BufferTexturePair textures_;
    int nodeCount_ = 0;
    std::vector<int> treeItems_;
};

}  // namespace raylab
