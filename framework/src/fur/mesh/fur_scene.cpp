#include "fur_scene.h"

#include "error.h"
#include "json_reader.h"
#include "mesh_shapes.h"
#include "obj_mesh.h"
#include "paths.h"
#include "text_format.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

struct FurSceneReader : JsonReader {
    std::filesystem::path folder;

    std::filesystem::path existingFile(const json& v, const std::string& where) const {
        std::filesystem::path p = (folder / string(v, where)).lexically_normal();
        std::error_code ec;
        if (!std::filesystem::exists(p, ec))
            fail(where, "file " + displayPath(p) + " does not exist");
        if (std::filesystem::is_directory(p, ec))
            fail(where, displayPath(p) + " is a folder, not a file");
        if (!std::filesystem::is_regular_file(p, ec))
            fail(where, displayPath(p) + " is not a regular file (a device, a pipe or a socket)");
        return p;
    }
    int integer(const json& v, const std::string& where, int lo, int hi) const {
        if (!v.is_number_integer()) fail(where, "expected a whole number");
        long long i = v.get<long long>();
        if (i < lo || i > hi)
            fail(where, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
        return int(i);
    }
    float within(const json& v, const std::string& where, float lo, float hi) const {
        float f = number(v, where);
        if (!(f >= lo && f <= hi))
            fail(where, "must be between " + significant(lo, 6) + " and " + significant(hi, 6));
        return f;
    }
};

void readMesh(const FurSceneReader& r, const json& doc, FurScene& s) {
    const json& m = r.member(doc, "scene", "mesh");
    r.allowOnly(m, "mesh", {"shape", "detail", "obj", "fit", "uvs"});
    if (m.contains("obj") == m.contains("shape"))
        r.fail("mesh", "give either \"shape\" (sphere, torus, cube) or \"obj\" (a file)");
    if (m.contains("obj")) {
        s.mesh.obj = r.existingFile(m["obj"], "mesh.obj");
        if (m.contains("fit")) {
            if (!m["fit"].is_boolean()) r.fail("mesh.fit", "expected true or false");
            s.mesh.fit = m["fit"].get<bool>();
        }
        if (m.contains("uvs")) {
            const std::string uvs = r.string(m["uvs"], "mesh.uvs");
            if (uvs != "sphere" && uvs != "box")
                r.fail("mesh.uvs", "expected \"sphere\" or \"box\" (not '" + uvs + "')");
            s.mesh.uvs = uvs == "box" ? UvProjection::Box : UvProjection::Sphere;
        }
        return;
    }
    if (m.contains("uvs")) r.fail("mesh.uvs", "is for OBJ models (the shapes have their own)");
    if (m.contains("fit"))
        r.fail("mesh.fit", "is for OBJ models (the shapes are made to fit the box already)");
    s.mesh.shape = r.string(m["shape"], "mesh.shape");
    const auto& names = shapeNames();
    if (std::find(names.begin(), names.end(), s.mesh.shape) == names.end())
        r.fail("mesh.shape", "unknown shape '" + s.mesh.shape + "' (known: sphere, torus, cube)");
    if (m.contains("detail")) s.mesh.detail = r.integer(m["detail"], "mesh.detail", 2, 512);
}

void readFur(const FurSceneReader& r, const json& doc, FurScene& s) {
    const json& f = r.member(doc, "scene", "fur");
    r.allowOnly(f, "fur",
                {"length", "shells", "pattern_scale", "shadow_intensity", "color_map", "pattern",
                 "fin_map", "gravity", "strand_density", "strand_segments"});
    FurParameters& p = s.fur;
    if (f.contains("length")) p.length = r.positive(f["length"], "fur.length");
    if (f.contains("shells")) p.shells = r.integer(f["shells"], "fur.shells", 1, 256);
    if (f.contains("pattern_scale"))
        p.patternScale = r.positive(f["pattern_scale"], "fur.pattern_scale");
    if (f.contains("shadow_intensity"))
        p.shadowIntensity = r.within(f["shadow_intensity"], "fur.shadow_intensity", 0.0f, 1.0f);
    p.colorMap = r.existingFile(r.member(f, "fur", "color_map"), "fur.color_map");
    p.pattern = r.existingFile(r.member(f, "fur", "pattern"), "fur.pattern");
    p.finMap = r.existingFile(r.member(f, "fur", "fin_map"), "fur.fin_map");
    if (f.contains("gravity")) p.gravity = r.within(f["gravity"], "fur.gravity", 0.0f, 2.0f);
    if (f.contains("strand_density"))
        p.strandDensity = r.within(f["strand_density"], "fur.strand_density", 1.0f, 1e6f);
    if (f.contains("strand_segments"))
        p.strandSegments = r.integer(f["strand_segments"], "fur.strand_segments", 1, 16);
}

}  // namespace

glm::mat4 FurScene::modelMatrix(float timeSeconds) const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
    m = glm::rotate(m, glm::radians(rotateDeg.y + spinDegPerSecond * timeSeconds),
                    glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotateDeg.x), glm::vec3(1, 0, 0));
    m = glm::rotate(m, glm::radians(rotateDeg.z), glm::vec3(0, 0, 1));
    return glm::scale(m, scale);
}

FurScene loadFurScene(const std::filesystem::path& file) {
    FurScene s;
    s.file = displayPath(file);
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw Error("scene file " + s.file + " does not exist");
    const json doc = parseJsonFile(file, s.file);
    FurSceneReader r{{s.file}, file.parent_path()};
    if (!doc.is_object()) r.fail("scene", "expected an object");
    if (!doc.contains("mesh") && (doc.contains("spheres") || doc.contains("materials")))
        r.fail("scene", "a ray-tracing scene (it has spheres or materials, no mesh): fur stages "
                        "draw fur scenes (assets/scenes/fur/)");
    r.allowOnly(doc, "", {"background", "camera", "mesh", "transform", "light", "fur"});
    s.background = r.color(r.member(doc, "scene", "background"), "background");
    const SceneCamera camera = readSceneCamera(r, doc);
    s.camera = camera.pose;
    s.fovYDeg = camera.fovYDeg;
    readMesh(r, doc, s);
    if (doc.contains("transform")) {
        const json& t = doc["transform"];
        r.allowOnly(t, "transform", {"translate", "rotate", "scale", "spin"});
        if (t.contains("translate")) s.translate = r.vec3(t["translate"], "transform.translate");
        if (t.contains("rotate")) s.rotateDeg = r.vec3(t["rotate"], "transform.rotate");
        if (t.contains("scale")) {
            s.scale = r.vec3(t["scale"], "transform.scale");
            for (int i = 0; i < 3; ++i)
                if (!(s.scale[i] > 0.0f))
                    r.fail("transform.scale", "every factor must be positive (a mirror would "
                                              "turn the triangles inside out)");
        }
        if (t.contains("spin")) s.spinDegPerSecond = r.number(t["spin"], "transform.spin");
    }
    const json& l = r.member(doc, "scene", "light");
    r.allowOnly(l, "light", {"direction", "color", "ambient"});
    s.lightDirection = r.direction(r.member(l, "light", "direction"), "light.direction");
    if (l.contains("color")) s.lightColor = r.color(l["color"], "light.color");
    if (l.contains("ambient")) s.ambient = r.color(l["ambient"], "light.ambient");
    readFur(r, doc, s);
    return s;
}

Mesh loadFurMesh(const FurScene& scene, MeshPlacement* placement) {
    if (scene.mesh.obj.empty()) {
        Mesh m = makeShape(scene.mesh.shape, scene.mesh.detail);
        validateMesh(m);
        if (placement) *placement = MeshPlacement{};
        return m;
    }
    Mesh m = loadObjMesh(scene.mesh.obj, scene.mesh.uvs);
    MeshPlacement p;
    p.fromObj = true;
    p.triangles = m.indices.size() / 3;
    p.lo = p.hi = m.positions.front();
    for (const glm::vec3& v : m.positions) {
        p.lo = glm::min(p.lo, v);
        p.hi = glm::max(p.hi, v);
    }
    const glm::vec3 size = p.hi - p.lo;
    const float longest = std::max({size.x, size.y, size.z});
    if (scene.mesh.fit && longest > 0.0f) {
        p.fitted = true;
        p.centre = 0.5f * (p.lo + p.hi);
        p.scale = 2.0f / longest;
        for (glm::vec3& v : m.positions) v = (v - p.centre) * p.scale;
        // Normals keep their directions under a uniform scale.
    }
    validateMesh(m);
    if (placement) *placement = p;
    return m;
}

std::string describePlacement(const MeshPlacement& p, const std::string& file) {
    if (!p.fromObj) return "";
    auto point = [](const glm::vec3& v) {
        return "(" + significant(v.x, 4) + ", " + significant(v.y, 4) + ", " + significant(v.z, 4) +
               ")";
    };
    std::string text = "mesh " + file + ": " + std::to_string(p.triangles) + " triangles, bounds " +
                       point(p.lo) + " .. " + point(p.hi);
    if (p.fitted)
        text += "; fitted to the box from -1 to 1: centred on " + point(p.centre) + ", scaled by " +
                significant(p.scale, 4) +
                " (\"fit\": false in the scene's mesh keeps the file's coordinates)";
    else text += ", as the file gives them (\"fit\": false)";
    return text;
}

}  // namespace raylab
