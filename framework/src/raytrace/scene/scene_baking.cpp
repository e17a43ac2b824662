#include "scene_baking.h"
#include "gpu_values.h"
#include "shell_slots.h"
#include "text_format.h"
#include "triangle_groups.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

namespace raylab {

namespace {

// A float literal GLSL reads back as exactly the same float: 9 significant
// digits, and always with a '.' or an exponent (a bare "1" would be an int).
std::string literal(float v) {
    std::string s = significant(double(v), 9);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string vec3Literal(glm::vec3 v) {
    return "vec3(" + literal(v.x) + ", " + literal(v.y) + ", " + literal(v.z) + ")";
}
std::string vec4Literal(glm::vec4 v) {
    return "vec4(" + literal(v.x) + ", " + literal(v.y) + ", " + literal(v.z) + ", " +
           literal(v.w) + ")";
}

// "const TYPE NAME[N] = TYPE[N](a, b, ...);" - with one dummy element when
// the list is empty (the shader still declares the array).
template <class T>
std::string constArray(const char* type, const char* name, const std::vector<T>& values,
                       const std::function<std::string(const T&)>& format,
                       const std::string& dummy) {
    std::string n = std::to_string(std::max<std::size_t>(1, values.size()));
    std::string out =
        std::string("const ") + type + " " + name + "[" + n + "] = " + type + "[" + n + "](";
    if (values.empty()) out += dummy;
    for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + format(values[i]);
    return out + ");\n";
}

std::string floats(const char* name, const std::vector<float>& v) {
    return constArray<float>(
        "float", name, v, [](const float& x) { return literal(x); }, "0.0");
}
std::string ints(const char* name, const std::vector<int>& v) {
    return constArray<int>(
        "int", name, v, [](const int& x) { return std::to_string(x); }, "0");
}
std::string vec3s(const char* name, const std::vector<glm::vec3>& v) {
    return constArray<glm::vec3>(
        "vec3", name, v, [](const glm::vec3& x) { return vec3Literal(x); }, "vec3(0.0)");
}
std::string vec4s(const char* name, const std::vector<glm::vec4>& v) {
    return constArray<glm::vec4>(
        "vec4", name, v, [](const glm::vec4& x) { return vec4Literal(x); }, "vec4(0.0)");
}
std::string constInt(const char* name, int v) {
    return std::string("const int ") + name + " = " + std::to_string(v) + ";\n";
}

template <class T, class F>
auto gather(const std::vector<T>& list, F f) {
    std::vector<decltype(f(list.front()))> out;
    for (const T& x : list) out.push_back(f(x));
    return out;
}

// The groups that are box-like shells (shell_slots.h), for the demo's
// program: only for scenes that have one, so that the others' programs
// stay as they were.
std::string shellSlotsGlsl(const Scene& scene, const std::vector<TriangleGroup>& groups) {
    const std::vector<std::vector<ShellSlot>> slots = shellSlots(scene, groups);
    std::vector<int> firstSlot;
    std::vector<glm::vec4> planes, sides;
    for (const std::vector<ShellSlot>& group : slots) {
        firstSlot.push_back(group.empty() ? -1 : int(planes.size()));
        for (const ShellSlot& s : group) {
            planes.emplace_back(glm::vec3(s.normal), float(s.top));
            sides.emplace_back(float(s.bottom), float(s.topTriangle), float(s.bottomTriangle),
                               0.0f);
        }
    }
    if (planes.empty()) return {};
    return ints("uTriangleGroupSlot", firstSlot) + vec4s("uShellSlotPlane", planes) +
           vec4s("uShellSlotSides", sides);
}

}  // namespace

std::string bakedSceneGlsl(const Scene& scene, bool spheresInStorage) {
    std::string g =
        "// The scene, compiled in (framework/src/raytrace/scene/scene_baking.cpp): " + scene.file +
        "\n";
    g += "const vec3 uBackground = " + vec3Literal(scene.background) + ";\n";

    g += constInt("uSphereCount", int(scene.spheres.size()));
    if (!spheresInStorage) {
        g += vec3s("uSphereColors", gather(scene.spheres, [&](const Sphere& s) {
                       return scene.materials[std::size_t(s.material)].diffuse;
                   }));
        g += ints("uSphereMaterial",
                  gather(scene.spheres, [](const Sphere& s) { return s.material; }));
    }

    const auto& m = scene.materials;
    g += vec3s("uMatAmbient", gather(m, [](const Material& x) { return x.ambient; }));
    g += vec3s("uMatDiffuse", gather(m, [](const Material& x) { return x.diffuse; }));
    g += vec3s("uMatSpecular", gather(m, [](const Material& x) { return x.specular; }));
    g += floats("uMatShininess", gather(m, [](const Material& x) { return x.shininess; }));
    g += ints("uMatType", gather(m, [](const Material& x) { return int(x.type); }));
    g += floats("uMatIor", gather(m, [](const Material& x) { return x.ior; }));
    g += vec3s("uMatN", gather(m, [](const Material& x) { return x.n; }));
    g += vec3s("uMatK", gather(m, [](const Material& x) { return x.k; }));
    g += ints("uMatTexture", gather(m, [](const Material& x) { return x.texture; }));
    g += ints("uMatNormalMap", gather(m, [](const Material& x) { return x.normalMap; }));

    g += constInt("uLightCount", int(scene.lights.size()));
    g += vec3s("uLightPositions",
               gather(scene.lights, [](const PointLight& l) { return gpuPoint(l.position); }));
    g += vec3s("uLightColors", gather(scene.lights, [](const PointLight& l) { return l.color; }));

    g += constInt("uPlaneCount", int(scene.planes.size()));
    g += vec4s("uPlanes", gather(scene.planes, gpuPlane));
    g += floats("uPlaneTileSize",
                gather(scene.planes, [](const Plane& p) { return float(p.tileSize); }));
    g += ints("uPlaneMaterial", gather(scene.planes, [](const Plane& p) { return p.material; }));

    g += constInt("uDiscCount", int(scene.discs.size()));
    g += vec4s("uDiscs", gather(scene.discs, gpuDisc));
    g += vec3s("uDiscNormals", gather(scene.discs, [](const Disc& d) { return d.normal; }));
    g += ints("uDiscMaterial", gather(scene.discs, [](const Disc& d) { return d.material; }));

    std::vector<glm::vec3> vertices;
    for (const Triangle& t : scene.triangles)
        for (const glm::dvec3& v : t.vertices) vertices.push_back(gpuPoint(v));
    g += constInt("uTriangleCount", int(scene.triangles.size()));
    g += vec3s("uTriangleVertices", vertices);
    g += ints("uTriangleMaterial",
              gather(scene.triangles, [](const Triangle& t) { return t.material; }));
    const std::vector<TriangleGroup> groups = triangleGroups(scene);
    g += constInt("uTriangleGroupCount", int(groups.size()));
    g += vec4s("uTriangleGroupLow", gather(groups, [](const TriangleGroup& t) {
                   return glm::vec4(gpuPoint(t.lo), float(t.first));
               }));
    g += vec4s("uTriangleGroupHigh", gather(groups, [](const TriangleGroup& t) {
                   return glm::vec4(gpuPoint(t.hi), float(t.count));
               }));
    g += shellSlotsGlsl(scene, groups);

    g += constInt("uTorusCount", int(scene.tori.size()));
    g += vec4s("uTori", gather(scene.tori, gpuTorus));
    g += floats("uTorusMinor",
                gather(scene.tori, [](const Torus& t) { return float(t.minorRadius); }));
    g += ints("uTorusMaterial", gather(scene.tori, [](const Torus& t) { return t.material; }));

    // Only for scenes with meshes: the others' programs stay as they were
    // (the web build bakes the same text and has no meshes).
    if (!scene.meshes.empty()) g += constInt("uMeshTriangleCount", int(meshTriangleCount(scene)));

    g += constInt("uHasSky", scene.skyBox ? 1 : 0);
    g += constInt("uGlowSphere", scene.glow.sphere);
    g += "const vec3 uGlowColor = " + vec3Literal(scene.glow.color) + ";\n";
    g += "const float uGlowSize = " + literal(scene.glow.size) + ";\n";
    return g;
}

std::vector<std::string> bakedSceneDefines(const Scene& scene) {
    auto size = [](const char* name, std::size_t n) {
        return std::string(name) + " " + std::to_string(std::max<std::size_t>(1, n));
    };
    return {"SCENE_BAKED",
            size("MAX_SPHERES", scene.spheres.size()),
            size("MAX_MATERIALS", scene.materials.size()),
            size("MAX_LIGHTS", scene.lights.size()),
            size("MAX_PLANES", scene.planes.size()),
            size("MAX_DISCS", scene.discs.size()),
            size("MAX_TRIANGLES", scene.triangles.size()),
            size("MAX_TORI", scene.tori.size())};
}

}  // namespace raylab
