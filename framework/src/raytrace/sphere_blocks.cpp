#include "sphere_blocks.h"

#include "error.h"
#include "gpu_values.h"

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

SphereArrayLimits sphereArrayLimits() {
    SphereArrayLimits limits;
    limits.uniformBlockBytes = maxUniformBlockBytes();
    GLint major = 0, minor = 0, fragmentBlocks = 0, bytes = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    // Optional entry points (gl_loader.cpp): null before OpenGL 4.3.
    if (major * 10 + minor < 43 || !glGetProgramResourceIndex || !glShaderStorageBlockBinding)
        return limits;
    glGetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &fragmentBlocks);
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);  // a GLint64: clamped to the int range
    if (fragmentBlocks >= 3) limits.storageBlockBytes = int(bytes);
    return limits;
}

bool spheresNeedStorage(const Scene& scene, const SphereArrayLimits& limits) {
    const std::size_t n = scene.spheres.size();
    const std::size_t inBlock = std::size_t(limits.uniformBlockBytes / kSphereBlockStride);
    const std::size_t inStorage = std::size_t(limits.storageBlockBytes / kSphereBlockStride);
    if (n <= inBlock) return false;
    if (n <= inStorage) return true;
    std::string why = scene.file + ": spheres: " + std::to_string(n) +
                      " spheres, but this GPU's uniform blocks hold at most " +
                      std::to_string(inBlock) + " (GL_MAX_UNIFORM_BLOCK_SIZE " +
                      std::to_string(limits.uniformBlockBytes) + " bytes, " +
                      std::to_string(kSphereBlockStride) + " per sphere)";
    if (limits.storageBlockBytes == 0) why += " and it has no storage blocks (OpenGL 4.3)";
    else
        why += " and its storage blocks " + std::to_string(inStorage) +
               " (GL_MAX_SHADER_STORAGE_BLOCK_SIZE " + std::to_string(limits.storageBlockBytes) +
               " bytes)";
    throw Error(why);
}

SphereBlocks::SphereBlocks(const Scene& scene, int slots, bool storage)
    : spheres_(scene.spheres), target_(storage ? GL_SHADER_STORAGE_BUFFER : GL_UNIFORM_BUFFER) {
    const std::size_t n = std::max<std::size_t>(std::size_t(std::max(slots, 1)), spheres_.size());
    centres_.assign(n, glm::vec4(0.0f));
    std::vector<glm::vec4> colours(n, glm::vec4(0.0f));
    std::vector<glm::ivec4> materials(n, glm::ivec4(0));  // std140: an int per 16 bytes
    firstMoving_ = spheres_.size();
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
        const Sphere& s = spheres_[i];
        centres_[i] = gpuSphere(s, shownTime_);
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
        if (!glGetProgramResourceIndex) continue;  // no storage blocks before OpenGL 4.3
        const GLuint storage =
            glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, kBlockNames[b]);
        if (storage != GL_INVALID_INDEX)
            glShaderStorageBlockBinding(program, storage, kFirstBindingPoint + b);
    }
}

void SphereBlocks::bind() const {
    for (GLuint b = 0; b < 3; ++b) glBindBufferBase(target_, kFirstBindingPoint + b, buffers_[b]);
}

void SphereBlocks::moveTo(float t) {
    if (endMoving_ == 0 || t == shownTime_) return;
    shownTime_ = t;
    for (std::size_t i = firstMoving_; i < endMoving_; ++i) {
        const Sphere& s = spheres_[i];
        centres_[i] = gpuSphere(s, t);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, buffers_[0]);
    glBufferSubData(GL_UNIFORM_BUFFER, GLintptr(firstMoving_ * kSphereBlockStride),
                    GLsizeiptr((endMoving_ - firstMoving_) * kSphereBlockStride),
                    centres_.data() + firstMoving_);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

}  // namespace raylab
