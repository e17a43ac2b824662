#include "scene.h"

#include "error.h"
#include "paths.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace raylab {

using nlohmann::json;

glm::vec3 Motion::offsetAt(float t) const {
    if (amplitude == 0.0f) return glm::vec3(0.0f);
    return axis * amplitude * std::sin(6.28318530718f * t / periodSeconds);
}

namespace {

// Reads values with messages that name the file and the JSON path.
struct Reader {
    const std::string& file;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(file + ": " + where + ": " + what);
    }
    const json& member(const json& obj, const std::string& where, const char* key) const {
        if (!obj.is_object()) fail(where, "expected an object");
        auto it = obj.find(key);
        if (it == obj.end()) fail(where, std::string("missing \"") + key + "\"");
        return *it;
    }
    float number(const json& v, const std::string& where) const {
        if (!v.is_number()) fail(where, "expected a number");
        double d = v.get<double>();
        if (!std::isfinite(d) || std::fabs(d) > 1e30) fail(where, "number out of range");
        return float(d);
    }
    float positive(const json& v, const std::string& where) const {
        float f = number(v, where);
        if (!(f > 0.0f)) fail(where, "expected a positive number");
        return f;
    }
    glm::vec3 vec3(const json& v, const std::string& where) const {
        if (!v.is_array() || v.size() != 3) fail(where, "expected [x, y, z]");
        return {number(v[0], where + "[0]"), number(v[1], where + "[1]"), number(v[2], where + "[2]")};
    }
    glm::vec3 color(const json& v, const std::string& where) const {
        glm::vec3 c = vec3(v, where);
        for (int i = 0; i < 3; ++i)
            if (c[i] < 0.0f || c[i] > 1.0f) fail(where, "colour components must lie in [0, 1]");
        return c;
    }
};

std::string lineColumn(const std::string& text, std::size_t byte) {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

} // namespace

Scene loadScene(const std::filesystem::path& file) {
    Scene scene;
    scene.file = displayPath(file);
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw Error("scene file " + scene.file + " does not exist");
    std::string text = readTextFile(file);
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        throw Error(scene.file + ": " + lineColumn(text, e.byte > 0 ? e.byte - 1 : 0) + ": JSON syntax error");
    }
    Reader r{scene.file};
    scene.background = r.color(r.member(doc, "scene", "background"), "background");
    const json& cam = r.member(doc, "scene", "camera");
    scene.camera.position = r.vec3(r.member(cam, "camera", "position"), "camera.position");
    scene.camera.yawDeg = r.number(r.member(cam, "camera", "yaw"), "camera.yaw");
    scene.camera.pitchDeg = r.number(r.member(cam, "camera", "pitch"), "camera.pitch");
    if (cam.contains("fov_y")) {
        scene.fovYDeg = r.positive(cam["fov_y"], "camera.fov_y");
        if (scene.fovYDeg >= 170.0f) r.fail("camera.fov_y", "must be below 170 degrees");
    }
    if (doc.contains("materials")) {
        const json& materials = doc["materials"];
        if (!materials.is_object()) r.fail("materials", "expected an object of named materials");
        for (const auto& [name, m] : materials.items()) {
            std::string where = "materials." + name;
            Material mat;
            mat.name = name;
            mat.ambient = r.color(r.member(m, where, "ambient"), where + ".ambient");
            mat.diffuse = r.color(r.member(m, where, "diffuse"), where + ".diffuse");
            mat.specular = r.color(r.member(m, where, "specular"), where + ".specular");
            mat.shininess = r.positive(r.member(m, where, "shininess"), where + ".shininess");
            std::string type = "plastic";
            if (m.contains("type")) {
                if (!m["type"].is_string()) r.fail(where + ".type", "expected plastic, mirror, glass or metal");
                type = m["type"].get<std::string>();
            }
            if (type == "plastic") mat.type = Material::Type::Plastic;
            else if (type == "mirror") mat.type = Material::Type::Mirror;
            else if (type == "glass") {
                mat.type = Material::Type::Glass;
                mat.ior = r.positive(r.member(m, where, "ior"), where + ".ior");
                if (mat.ior < 1.0f || mat.ior > 4.0f) r.fail(where + ".ior", "index of refraction must lie in [1, 4]");
            } else if (type == "metal") {
                mat.type = Material::Type::Metal;
                mat.n = r.vec3(r.member(m, where, "n"), where + ".n");
                mat.k = r.vec3(r.member(m, where, "k"), where + ".k");
                for (int c = 0; c < 3; ++c)
                    if (mat.n[c] <= 0.0f || mat.k[c] < 0.0f) r.fail(where, "n must be positive and k not negative");
            } else {
                r.fail(where + ".type", "unknown type \"" + type + "\" (plastic, mirror, glass or metal)");
            }
            scene.materials.push_back(mat);
        }
    }
    if (doc.contains("lights")) {
        const json& lights = doc["lights"];
        if (!lights.is_array()) r.fail("lights", "expected a list");
        for (std::size_t i = 0; i < lights.size(); ++i) {
            std::string where = "lights[" + std::to_string(i) + "]";
            PointLight light;
            light.position = r.vec3(r.member(lights[i], where, "position"), where + ".position");
            light.color = r.color(r.member(lights[i], where, "color"), where + ".color");
            scene.lights.push_back(light);
        }
    }
    const json& spheres = r.member(doc, "scene", "spheres");
    if (!spheres.is_array()) r.fail("spheres", "expected a list");
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        std::string where = "spheres[" + std::to_string(i) + "]";
        const json& s = spheres[i];
        Sphere sphere;
        sphere.center = r.vec3(r.member(s, where, "center"), where + ".center");
        sphere.radius = r.positive(r.member(s, where, "radius"), where + ".radius");
        if (s.is_object() && s.contains("material")) {
            if (!s["material"].is_string()) r.fail(where + ".material", "expected the name of a material");
            std::string name = s["material"].get<std::string>();
            auto it = std::find_if(scene.materials.begin(), scene.materials.end(), [&](const Material& m) { return m.name == name; });
            if (it == scene.materials.end()) r.fail(where + ".material", "unknown material \"" + name + "\"");
            sphere.material = int(it - scene.materials.begin());
        } else {
            Material flat;
            flat.name = where;
            flat.diffuse = r.color(r.member(s, where, "color"), where + ".color");
            sphere.material = int(scene.materials.size());
            scene.materials.push_back(flat);
        }
        if (s.contains("motion")) {
            const json& m = s["motion"];
            std::string mw = where + ".motion";
            sphere.motion.axis = r.vec3(r.member(m, mw, "axis"), mw + ".axis");
            sphere.motion.amplitude = r.number(r.member(m, mw, "amplitude"), mw + ".amplitude");
            sphere.motion.periodSeconds = r.positive(r.member(m, mw, "period"), mw + ".period");
        }
        scene.spheres.push_back(sphere);
    }
    return scene;
}

} // namespace raylab
