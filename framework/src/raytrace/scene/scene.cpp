#include "scene.h"

#include "error.h"
#include "paths.h"
#include "scene_reader.h"

#include <algorithm>
#include <cmath>

namespace raylab {

glm::dvec3 Motion::offsetAt(float t) const {
    if (amplitude == 0.0) return glm::dvec3(0.0);
    return glm::dvec3(axis) * amplitude * std::sin(6.283185307179586 * double(t) / periodSeconds);
}

namespace {

// The texture layer of an image file; files used twice share a layer.
int textureLayer(Scene& scene, const std::filesystem::path& file) {
    auto it = std::find(scene.textures.begin(), scene.textures.end(), file);
    if (it != scene.textures.end()) return int(it - scene.textures.begin());
    scene.textures.push_back(file);
    return int(scene.textures.size()) - 1;
}

Material::Type materialType(const SceneReader& r, const json& m, const std::string& where) {
    std::string type = m.contains("type") ? r.string(m["type"], where + ".type") : "plastic";
    if (type == "plastic") return Material::Type::Plastic;
    if (type == "mirror") return Material::Type::Mirror;
    if (type == "glass") return Material::Type::Glass;
    if (type == "metal") return Material::Type::Metal;
    r.fail(where + ".type", "unknown type \"" + type + "\" (plastic, mirror, glass or metal)");
}

void readMaterials(const SceneReader& r, const json& doc, Scene& scene) {
    if (!doc.contains("materials")) return;
    const json& materials = doc["materials"];
    if (!materials.is_object()) r.fail("materials", "expected an object of named materials");
    for (const auto& [name, m] : materials.items()) {
        std::string where = "materials." + name;
        r.allowOnly(m, where,
                    {"ambient", "diffuse", "specular", "shininess", "type", "ior", "n", "k",
                     "texture", "normal_map"});
        Material mat;
        mat.name = name;
        mat.ambient = r.color(r.member(m, where, "ambient"), where + ".ambient");
        mat.diffuse = r.color(r.member(m, where, "diffuse"), where + ".diffuse");
        mat.specular = r.color(r.member(m, where, "specular"), where + ".specular");
        mat.shininess = r.positive(r.member(m, where, "shininess"), where + ".shininess");
        mat.type = materialType(r, m, where);
        if (mat.type == Material::Type::Glass) {
            mat.ior = r.positive(r.member(m, where, "ior"), where + ".ior");
            if (mat.ior < 1.0f || mat.ior > 4.0f)
                r.fail(where + ".ior", "index of refraction must lie in [1, 4]");
        } else if (mat.type == Material::Type::Metal) {
            mat.n = r.vec3(r.member(m, where, "n"), where + ".n");
            mat.k = r.vec3(r.member(m, where, "k"), where + ".k");
            for (int c = 0; c < 3; ++c)
                if (mat.n[c] <= 0.0f || mat.k[c] < 0.0f)
                    r.fail(where, "n must be positive and k not negative");
        }
        if (m.contains("texture"))
            mat.texture = textureLayer(scene, r.existingFile(m["texture"], where + ".texture"));
        if (m.contains("normal_map"))
            mat.normalMap =
                textureLayer(scene, r.existingFile(m["normal_map"], where + ".normal_map"));
        scene.materials.push_back(mat);
    }
}

void readLights(const SceneReader& r, const json& doc, Scene& scene) {
    const json& lights = r.optionalList(doc, "lights");
    for (std::size_t i = 0; i < lights.size(); ++i) {
        std::string where = "lights[" + std::to_string(i) + "]";
        r.allowOnly(lights[i], where, {"position", "color"});
        PointLight light;
        light.position = r.point(r.member(lights[i], where, "position"), where + ".position");
        light.color = r.color(r.member(lights[i], where, "color"), where + ".color");
        scene.lights.push_back(light);
    }
}

// "sky_box": six image files, in the order +x, -x, +y, -y, +z, -z.
void readSkyBox(const SceneReader& r, const json& doc, Scene& scene) {
    if (!doc.contains("sky_box")) return;
    const json& faces = doc["sky_box"];
    if (!faces.is_array() || faces.size() != 6)
        r.fail("sky_box", "expected six image files: +x, -x, +y, -y, +z, -z");
    std::array<std::filesystem::path, 6> files;
    for (std::size_t i = 0; i < 6; ++i)
        files[i] = r.existingFile(faces[i], "sky_box[" + std::to_string(i) + "]");
    scene.skyBox = files;
}

void readGlow(const SceneReader& r, const json& doc, Scene& scene) {
    if (!doc.contains("glow")) return;
    const json& g = doc["glow"];
    r.allowOnly(g, "glow", {"sphere", "color", "size"});
    const json& sphere = r.member(g, "glow", "sphere");
    if (!sphere.is_number_integer() || sphere.get<long long>() < 0 ||
        sphere.get<long long>() >= (long long)scene.spheres.size())
        r.fail("glow.sphere", "expected the index of a sphere (0.." +
                                  std::to_string(int(scene.spheres.size()) - 1) + ")");
    scene.glow.sphere = sphere.get<int>();
    if (g.contains("color")) scene.glow.color = r.color(g["color"], "glow.color");
    if (g.contains("size")) scene.glow.size = r.positive(g["size"], "glow.size");
}

}  // namespace

Scene loadScene(const std::filesystem::path& file) {
    Scene scene;
    scene.file = displayPath(file);
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
        throw Error("scene file " + scene.file + " does not exist");
    const json doc = parseJsonFile(file, scene.file);
    SceneReader r{{scene.file}, file.parent_path()};
    if (!doc.is_object()) r.fail("scene", "expected an object");
    if (doc.contains("mesh") || doc.contains("fur"))
        r.fail("scene", "a fur scene (it has a mesh or fur): ray-tracing stages draw ray-tracing "
                        "scenes (assets/scenes/*.json)");
    r.allowOnly(doc, "",
                {"background", "camera", "materials", "lights", "spheres", "planes", "discs",
                 "triangles", "rectangles", "boxes", "tori", "meshes", "sky_box", "glow"});
    scene.background = r.color(r.member(doc, "scene", "background"), "background");
    const SceneCamera camera = readSceneCamera(r, doc);
    scene.camera = camera.pose;
    scene.fovYDeg = camera.fovYDeg;
    readMaterials(r, doc, scene);
    readLights(r, doc, scene);
    readShapes(r, doc, scene);
    readSkyBox(r, doc, scene);
    readGlow(r, doc, scene);
    return scene;
}

glm::mat3 torusToLocal(glm::vec3 axis) {
    glm::vec3 helper = std::fabs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    glm::vec3 x = glm::normalize(glm::cross(helper, axis));
    glm::vec3 y = glm::cross(axis, x);
    return glm::transpose(glm::mat3(x, y, axis));  // rows x, y, axis
}

}  // namespace raylab
