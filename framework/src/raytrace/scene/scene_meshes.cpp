// The scene's triangle meshes ("meshes": OBJ files, stage 08), read by the
// same OBJ loader as the fur track (fur/mesh/obj_mesh.h).
#include "scene_reader.h"

#include "error.h"
#include "obj_mesh.h"
#include "shader_constants.h"

#include <filesystem>
#include <system_error>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// About 8 million triangles of a plain OBJ file; the limit is 1 million.
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(512) << 20;

// "scale": one positive number (uniform, so the normals stay as they are).
double scaleOf(const SceneReader& r, const json& m, const std::string& where) {
    return m.contains("scale") ? r.length(m["scale"], where + ".scale") : 1.0;
}

}  // namespace

void readMeshes(const SceneReader& r, const json& doc, Scene& scene) {
    const json& meshes = r.optionalList(doc, "meshes");
    std::size_t triangles = 0;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const std::string where = "meshes[" + std::to_string(i) + "]";
        const json& m = meshes[i];
        r.allowOnly(m, where, {"file", "translate", "scale", "material", "color"});
        MeshObject object;
        object.file = r.existingFile(r.member(m, where, "file"), where + ".file");
        const glm::dvec3 translate = m.contains("translate")
                                         ? r.point(m["translate"], where + ".translate")
                                         : glm::dvec3(0.0);
        const double scale = scaleOf(r, m, where);
        object.material = materialOf(r, m, where, scene);
        // Refused before it is read: parsing a file far larger than the
        // triangle limit allows would only cost memory and time first.
        std::error_code sizeError;
        const auto bytes = fs::file_size(object.file, sizeError);
        if (!sizeError && bytes > kMaxMeshFileBytes)
            r.fail(where + ".file", "the file has " + std::to_string(bytes >> 20) +
                                        " MB; mesh files of at most " +
                                        std::to_string(kMaxMeshFileBytes >> 20) + " MB are read");
        Mesh mesh;
        try {
            mesh = loadObjMesh(object.file);
        } catch (const Error& e) { r.fail(where + ".file", e.what()); }
        object = placeMesh(object.file, std::move(mesh), scale, translate, object.material);
        triangles += object.triangleCount();
        // Hit ids number a kind's objects below OBJECT_KIND_STRIDE.
        if (triangles >= std::size_t(shader::kObjectKindStride))
            r.fail(where, "the meshes have " + std::to_string(triangles) + " triangles; at most " +
                              std::to_string(shader::kObjectKindStride - 1) + " fit");
        const Material& material = scene.materials[std::size_t(object.material)];
        if (material.normalMap >= 0)
            r.fail(where + ".material",
                   "material \"" + material.name +
                       "\" has a normal map, but only spheres take normal maps");
        scene.meshes.push_back(std::move(object));
    }
}

MeshObject placeMesh(std::filesystem::path file, Mesh mesh, double scale,
                     const glm::dvec3& translate, int material) {
    MeshObject object;
    object.file = std::move(file);
    object.positions.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions)
        object.positions.push_back(glm::dvec3(p) * scale + translate);
    object.normals = std::move(mesh.normals);
    object.uvs = std::move(mesh.uvs);
    object.indices = std::move(mesh.indices);
    object.material = material;
    return object;
}

std::size_t meshTriangleCount(const Scene& scene) {
    std::size_t n = 0;
    for (const MeshObject& m : scene.meshes) n += m.triangleCount();
    return n;
}

std::vector<float> meshCornerTexels(const Scene& scene) {
    std::vector<float> corners;
    for (const MeshObject& m : scene.meshes) {
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = m.indices[3 * t + std::size_t(k)];
                const glm::vec3 p(m.positions[v]);  // the scene in the GPU's frame: small
                corners.insert(corners.end(), {p.x, p.y, p.z, m.uvs[v].x});
            }
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = m.indices[3 * t + std::size_t(k)];
                corners.insert(corners.end(),
                               {m.normals[v].x, m.normals[v].y, m.normals[v].z, m.uvs[v].y});
            }
        }
    }
    if (corners.empty()) corners.assign(4, 0.0f);
    return corners;
}

std::vector<int> meshTriangleMaterials(const Scene& scene) {
    std::vector<int> materials;
    for (const MeshObject& object : scene.meshes)
        materials.insert(materials.end(), object.triangleCount(), object.material);
    if (materials.empty()) materials.push_back(0);
    return materials;
}

}  // namespace raylab
