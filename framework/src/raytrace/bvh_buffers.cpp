#include "bvh_buffers.h"

#include "shader_constants.h"

#include <vector>

namespace raylab {

void fillTextureBuffer(GLuint buffer, GLuint texture, GLenum format, const void* data,
                       std::size_t bytes) {
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, texture);
    glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

BvhBuffers::BvhBuffers(const Bvh& bvh) : nodeCount_(int(bvh.nodes.size())) {
    std::vector<float> nodes;
    for (const BvhNode& n : bvh.nodes) {
        nodes.insert(nodes.end(), {n.box.lo.x, n.box.lo.y, n.box.lo.z, float(n.first)});
        // A leaf says what its items are: 8 * count + kind (bvh_access.glsl);
        // an inner node has 0 there.
        const int code = n.count > 0 ? kBvhLeafKinds * n.count + n.kind : 0;
        nodes.insert(nodes.end(), {n.box.hi.x, n.box.hi.y, n.box.hi.z, float(code)});
    }
    std::vector<GLint> items(bvh.items.begin(), bvh.items.end());
    // An empty buffer texture is not allowed everywhere: keep one dummy entry.
    if (nodes.empty()) nodes.assign(8, 0.0f);
    if (items.empty()) items.push_back(-1);
    glGenBuffers(2, buffers_);
    glGenTextures(2, textures_);
    fillTextureBuffer(buffers_[0], textures_[0], GL_RGBA32F, nodes.data(),
                      nodes.size() * sizeof(float));
    fillTextureBuffer(buffers_[1], textures_[1], GL_R32I, items.data(),
                      items.size() * sizeof(GLint));
}

BvhBuffers::~BvhBuffers() {
    glDeleteTextures(2, textures_);
    glDeleteBuffers(2, buffers_);
}

void BvhBuffers::bind(int nodeUnit, int itemUnit) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + nodeUnit));
    glBindTexture(GL_TEXTURE_BUFFER, textures_[0]);
    glActiveTexture(GLenum(GL_TEXTURE0 + itemUnit));
    glBindTexture(GL_TEXTURE_BUFFER, textures_[1]);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace raylab
