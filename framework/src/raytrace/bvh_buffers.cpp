#include "bvh_buffers.h"

#include "shader_constants.h"

#include <vector>

namespace raylab {

BvhBuffers::BvhBuffers(const Bvh& bvh)
    : nodeCount_(int(bvh.nodes.size())), treeItems_(bvh.items.begin(), bvh.items.end()) {
    std::vector<float> nodes;
    for (const BvhNode& n : bvh.nodes) {
        nodes.insert(nodes.end(), {n.box.lo.x, n.box.lo.y, n.box.lo.z, float(n.first)});
        // A leaf says what its items are: 8 * count + kind (bvh_access.glsl);
        // an inner node has 0 there.
        const int code = n.count > 0 ? kBvhLeafKinds * n.count + n.kind : 0;
        nodes.insert(nodes.end(), {n.box.hi.x, n.box.hi.y, n.box.hi.z, float(code)});
    }
    // An empty buffer texture is not allowed everywhere: keep one dummy entry.
    if (nodes.empty()) nodes.assign(8, 0.0f);
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
