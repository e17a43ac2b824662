#include "scene_mesh_buffers.h"

#include "error.h"

#include <vector>

namespace raylab {

SceneMeshBuffers::SceneMeshBuffers(const Scene& scene) {
    std::vector<float> corners;
    std::vector<GLint> materials;
    for (const MeshObject& object : scene.meshes) {
        const Mesh& m = object.mesh;
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = m.indices[3 * t + std::size_t(k)];
                corners.insert(corners.end(),
                               {m.positions[v].x, m.positions[v].y, m.positions[v].z, m.uvs[v].x});
            }
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = m.indices[3 * t + std::size_t(k)];
                corners.insert(corners.end(),
                               {m.normals[v].x, m.normals[v].y, m.normals[v].z, m.uvs[v].y});
            }
            materials.push_back(object.material);
        }
    }
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (corners.size() / 4 > std::size_t(maxTexels))
        throw Error(scene.file + ": meshes: " + std::to_string(materials.size()) +
                    " triangles need " + std::to_string(corners.size() / 4) +
                    " texels; this driver's buffer textures hold " + std::to_string(maxTexels));
    // An empty buffer texture is not allowed everywhere: keep one dummy entry.
    if (corners.empty()) corners.assign(4, 0.0f);
    if (materials.empty()) materials.push_back(0);
    textures_.fill(0, GL_RGBA32F, corners.data(), corners.size() * sizeof(float));
    textures_.fill(1, GL_R32I, materials.data(), materials.size() * sizeof(GLint));
}

}  // namespace raylab
