#include "bvh_buffers.h"

#include "bvh_boxes.h"
#include "shader_constants.h"

#include <vector>

namespace raylab {

BvhBuffers::BvhBuffers(const Bvh& bvh)
    : nodeCount_(int(bvh.nodes.size())), treeItems_(bvh.items.begin(), bvh.items.end()) {
    std::vector<float> nodes = packedBvhNodes(bvh);
    appendBvhBoxTexels(bvh, nodes);  // the eye-cells walk's one-texel nodes (bvh_boxes.h)
    textures_.fill(0, GL_RGBA32F, nodes.data(), nodes.size() * sizeof(float));
    fillItems({});
}

int BvhBuffers::setItemTail(const std::vector<int>& tail) {
    fillItems(tail);
    return int(treeItems_.size());
}

void BvhBuffers::fillItems(const std::vector<int>& tail) {
    std::vector<GLint> items(treeItems_.begin(), treeItems_.end());
    items.insert(items.end(), tail.begin(), tail.end());
    if (items.empty()) items.push_back(-1);
    textures_.fill(1, GL_R32I, items.data(), items.size() * sizeof(GLint));
}

}  // namespace raylab
