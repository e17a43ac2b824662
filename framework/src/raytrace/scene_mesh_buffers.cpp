#include "scene_mesh_buffers.h"

#include "error.h"

#include <vector>

namespace raylab {

SceneMeshBuffers::SceneMeshBuffers(const Scene& scene) {
    const std::vector<float> corners = meshCornerTexels(scene);
    const std::vector<int> list = meshTriangleMaterials(scene);
    const std::vector<GLint> materials(list.begin(), list.end());
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (corners.size() / 4 > std::size_t(maxTexels))
        throw Error(scene.file + ": meshes: " + std::to_string(meshTriangleCount(scene)) +
                    " triangles need " + std::to_string(corners.size() / 4) +
                    " texels; this driver's buffer textures hold " + std::to_string(maxTexels));
    textures_.fill(0, GL_RGBA32F, corners.data(), corners.size() * sizeof(float));
    textures_.fill(1, GL_R32I, materials.data(), materials.size() * sizeof(GLint));
}

}  // namespace raylab
