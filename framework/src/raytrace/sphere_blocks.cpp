#include "sphere_blocks.h"

#include "error.h"

#include <algorithm>

namespace raylab {

namespace {

// Binding points and block names, in the order of SphereBlocks::buffers_.
constexpr const char* kBlockNames[3] = {"SphereGeometry", "SphereColors", "SphereMaterials"};
constexpr GLuint kFirstBindingPoint = 0;

}  // namespace

int maxUniformBlockBytes() {
    GLint bytes = 0;
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &bytes);
    return int(bytes);
}

void checkSpheresFitBlock(const Scene& scene, int maxBlockBytes) {
    const int most = maxBlockBytes / kSphereBlockStride;
    if (scene.spheres.size() > std::size_t(most))
        throw Error(scene.file + ": spheres: " + std::to_string(scene.spheres.size()) +
                    " spheres, but this GPU's uniform blocks hold at most " + std::to_string(most) +
                    " (GL_MAX_UNIFORM_BLOCK_SIZE " + std::to_string(maxBlockBytes) + " bytes, " +
                    std::to_string(kSphereBlockStride) + " per sphere)");
}

SphereBlocks::SphereBlocks(const Scene& scene, int slots) : spheres_(scene.spheres) {
    const std::size_t n = std::max<std::size_t>(std::size_t(std::max(slots, 1)), spheres_.size());
    centres_.assign(n, glm::vec4(0.0f));
    std::vector<glm::vec4> colours(n, glm::vec4(0.0f));
    std::vector<glm::ivec4> materials(n, glm::ivec4(0));  // std140: an int per 16 bytes
    firstMoving_ = spheres_.size();
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
        const Sphere& s = spheres_[i];
        centres_[i] = glm::vec4(s.center + s.motion.offsetAt(shownTime_), s.radius);
        colours[i] = glm::vec4(scene.materials[std::size_t(s.material)].diffuse, 0.0f);
        materials[i].x = s.material;
        if (s.motion.amplitude != 0.0f) {
            firstMoving_ = std::min(firstMoving_, i);
            endMoving_ = i + 1;
        }
    }
    glGenBuffers(3, buffers_);
    const void* data[3] = {centres_.data(), colours.data(), materials.data()};
    for (int b = 0; b < 3; ++b) {
        glBindBuffer(GL_UNIFORM_BUFFER, buffers_[b]);
        // The centres change when spheres move; colours and materials never.
        glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(n * kSphereBlockStride), data[b],
                     b == 0 && endMoving_ > 0 ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

SphereBlocks::~SphereBlocks() { glDeleteBuffers(3, buffers_); }

void SphereBlocks::attach(GLuint program) {
    for (GLuint b = 0; b < 3; ++b) {
        const GLuint index = glGetUniformBlockIndex(program, kBlockNames[b]);
        if (index != GL_INVALID_INDEX)
            glUniformBlockBinding(program, index, kFirstBindingPoint + b);
    }
}

void SphereBlocks::bind() const {
    for (GLuint b = 0; b < 3; ++b)
        glBindBufferBase(GL_UNIFORM_BUFFER, kFirstBindingPoint + b, buffers_[b]);
}

void SphereBlocks::moveTo(float t) {
    if (endMoving_ == 0 || t == shownTime_) return;
    shownTime_ = t;
    for (std::size_t i = firstMoving_; i < endMoving_; ++i) {
        const Sphere& s = spheres_[i];
        centres_[i] = glm::vec4(s.center + s.motion.offsetAt(t), s.radius);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, buffers_[0]);
    glBufferSubData(GL_UNIFORM_BUFFER, GLintptr(firstMoving_ * kSphereBlockStride),
                    GLsizeiptr((endMoving_ - firstMoving_) * kSphereBlockStride),
                    centres_.data() + firstMoving_);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

}  // namespace raylab
