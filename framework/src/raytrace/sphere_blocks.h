#pragma once
// The scene's spheres on the GPU: three uniform buffers behind the shaders'
// uniform blocks SphereGeometry (uSpheres), SphereColors (uSphereColors) and
// SphereMaterials (uSphereMaterial) (framework/shaders/scene_spheres.glsl,
// scene_materials.glsl). Blocks, not plain uniform arrays: plain ones share
// about 1024 vec4s per fragment shader (NVIDIA) with everything else, a
// block holds GL_MAX_UNIFORM_BLOCK_SIZE bytes (64 KB on llvmpipe and
// NVIDIA: 4096 spheres) on its own.
// std140 gives every element of these arrays 16 bytes, an int or a vec3
// as much as a vec4: hence one block per array, each within the limit.
// A scene with more spheres than a uniform block holds gets the same three
// buffers as storage blocks (OpenGL 4.3, RAYLAB_SPHERE_STORAGE in the
// shaders, same std140 layout): their size is bounded by memory. Where the
// context has no storage buffers (OpenGL 3.3 to 4.2, WebGL 2) such a scene is
// refused in one line.
// Needs a current GL context. (Students need not read this file.)
#include "gl.h"
#include "scene.h"
#include "stage_programs.h"  // kSphereBlockStride

#include <string>
#include <vector>

namespace raylab {

// GL_MAX_UNIFORM_BLOCK_SIZE of the current context.
int maxUniformBlockBytes();

// What a context offers the spheres' arrays.
struct SphereArrayLimits {
    int uniformBlockBytes = 0;  // GL_MAX_UNIFORM_BLOCK_SIZE
    int storageBlockBytes = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE (capped at 2^31 - 1); 0: none
};

// The current context's limits: storage blocks only from OpenGL 4.3 on, with
// three of them allowed in a fragment shader and their functions loaded.
SphereArrayLimits sphereArrayLimits();

// Whether SCENE's spheres need storage blocks: false when they fit a uniform
// block. Throws Error (one line naming the limits) when neither holds them.
// Apart from the GL query, for tests.
bool spheresNeedStorage(const Scene& scene, const SphereArrayLimits& limits);

class SphereBlocks {
public:
    // SLOTS: the arrays' declared length (MAX_SPHERES, sphereSlots()): the
    // buffers hold that many entries, zero beyond the scene's spheres (as
    // plain uniform arrays read), so a block never reads past its buffer.
    // STORAGE: bind the buffers as storage blocks (spheresNeedStorage()).
    SphereBlocks(const Scene& scene, int slots, bool storage);
    ~SphereBlocks();
    SphereBlocks(const SphereBlocks&) = delete;
    SphereBlocks& operator=(const SphereBlocks&) = delete;

    // Ties PROGRAM's blocks, uniform or storage, to this class's binding
    // points (a block the program lacks or never reads is skipped). Once per
    // program.
    static void attach(GLuint program);
    // Binds the buffers to the binding points: every frame, since other
    // renderers in the same context use the same points.
    void bind() const;
    // Moves the spheres with a motion to time T: only the range from the
    // first to the last moving sphere is uploaded; nothing when none moves.
    void moveTo(float t);

private:
    std::vector<Sphere> spheres_;
    std::size_t firstMoving_ = 0, endMoving_ = 0;  // [first, end) holds every moving sphere
    std::vector<glm::vec4> centres_;               // the uSpheres block's contents
    float shownTime_ = 0.0f;                       // the time centres_ hold
    GLuint buffers_[3] = {0, 0, 0};                // geometry, colours, materials
    GLenum target_ = GL_UNIFORM_BUFFER;            // or GL_SHADER_STORAGE_BUFFER
};

}  // namespace raylab
