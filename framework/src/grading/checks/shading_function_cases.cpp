// The function-check tables of the functions that need a scene: lights,
// spheres, a material, a normal-map texel or a key's uniform. The harness
// stands in for the scene with plain globals (the prelude) that a helper
// fills from the case's inputs, so each case is a scene of its own.
#include "shading_function_cases.h"

#include "function_compare.h"

#ifndef RAYLAB_REFERENCES_AS_DATA  // the references: not in the page's core or a student build
#include "reference_intersect.h"
#include "reference_shading.h"
#endif

#include <cmath>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

FunctionCase makeCase(std::string label, dvec4 a0, dvec4 a1 = dvec4(0.0), dvec4 a2 = dvec4(0.0),
                      dvec4 a3 = dvec4(0.0)) {
    FunctionCase c;
    c.label = std::move(label);
    c.in = {a0, a1, a2, a3};
    return c;
}

// Within a relative TOLERANCE of the larger of 1 and WANT's largest component.
std::string compareColor(const FunctionCase& c, const dvec4& got, const dvec4& want,
                         double tolerance) {
    const double scale = std::max({1.0, std::fabs(want.x), std::fabs(want.y), std::fabs(want.z)});
    return compareVector(c, got, want, 3, tolerance * scale);
}

// ---- 02 blinn_phong.glsl ---------------------------------------------------

#ifndef RAYLAB_REFERENCES_AS_DATA
// The scene's lights (scene_lights.glsl) as globals the helper sets.
const char* kShadingLights = "// Stand-ins for the scene's lights, set by the case.\n"
                             "int uLightCount;\n"
                             "vec3 uLightPositions[MAX_LIGHTS];\n"
                             "vec3 uLightColors[MAX_LIGHTS];\n";
#endif

// The material and light colours of every blinnPhong case: each channel
// different, so a colour forgotten or taken from the wrong term shows.
// (maybe_unused here and below: only the references use them, and the
// page's core is built without them.)
[[maybe_unused]] const dvec3 kAmbient(0.1, 0.05, 0.02), kDiffuse(0.5, 0.6, 0.7),
    kSpecular(0.9, 0.8, 0.7);
[[maybe_unused]] const dvec3 kLightColor[2] = {{1.0, 0.8, 0.6}, {0.3, 0.5, 0.9}};

// a0: the unit normal, a0.w the shininess; a1: the unit direction to the eye;
// a2: light 0's position; a3: light 1's, a3.w = 0 for one light only. The
// point is the origin.
FunctionCase blinnCase(std::string label, dvec3 normal, dvec3 toEye, double shininess, dvec3 light0,
                       dvec3 light1 = dvec3(0.0), bool twoLights = false) {
    label += " [N " + caseVector(glm::normalize(normal)) + ", to the eye " +
             caseVector(glm::normalize(toEye)) + ", shininess " + caseNumber(shininess) +
             ", light at " + caseVector(light0) + (twoLights ? " and " + caseVector(light1) : "") +
             "]";
    return makeCase(std::move(label), dvec4(glm::normalize(normal), shininess),
                    dvec4(glm::normalize(toEye), 0.0), dvec4(light0, 0.0),
                    dvec4(light1, twoLights ? 1.0 : 0.0));
}

FunctionSpec blinnPhongSpec() {
    FunctionSpec s;
    s.name = "blinnPhong";
    s.prelude = RAYLAB_HARNESS_GLSL(kShadingLights);
    s.includes = {"ray.glsl", "scene_materials.glsl", "blinn_phong.glsl"};
    s.helpers =
        RAYLAB_HARNESS_GLSL("vec4 checkBlinnPhong(vec4 a0, vec4 a1, vec4 a2, vec4 a3)\n"
                            "{\n"
                            "    uLightCount = a3.w > 0.0 ? 2 : 1;\n"
                            "    uLightPositions[0] = a2.xyz;\n"
                            "    uLightColors[0] = vec3(1.0, 0.8, 0.6);\n"
                            "    uLightPositions[1] = a3.xyz;\n"
                            "    uLightColors[1] = vec3(0.3, 0.5, 0.9);\n"
                            "    Material m;\n"
                            "    m.ambient = vec3(0.1, 0.05, 0.02);\n"
                            "    m.diffuse = vec3(0.5, 0.6, 0.7);\n"
                            "    m.specular = vec3(0.9, 0.8, 0.7);\n"
                            "    m.shininess = a0.w;\n"
                            "    m.type = 0;\n"
                            "    m.ior = 1.0;\n"
                            "    m.n = vec3(0.0);\n"
                            "    m.k = vec3(0.0);\n"
                            "    m.texture = -1;\n"
                            "    m.normalMap = -1;\n"
                            "    return vec4(blinnPhong(vec3(0.0), a0.xyz, a1.xyz, m), 1.0);\n"
                            "}\n");
    s.call = "checkBlinnPhong(a0, a1, a2, a3)";
    const dvec3 up(0, 1, 0);
    s.cases = {
        blinnCase("light and eye straight above", up, up, 20, {0, 5, 0}),
        blinnCase("light at 60 degrees, eye above", up, up, 20,
                  5.0 * glm::normalize(dvec3(std::sqrt(3.0), 1, 0))),
        blinnCase("eye in the mirror direction (N . H = 1)", up, {3, 4, 0}, 30, {-3, 4, 0}),
        blinnCase("eye off the mirror direction", up, {1, 4, 2}, 30, {-3, 4, 0}),
        blinnCase("tilted normal, shininess 80", {0.3, 0.8, -0.5}, {0.1, 1, 0.3}, 80, {1.5, 4, -2}),
        blinnCase("two lights of different colours", up, {0.2, 1, 0.4}, 16, {-3, 4, 1}, {2, 3, -2},
                  true),
        blinnCase("light behind the surface (N . L < 0): ambient only", up, up, 20, {1, -4, 0}),
        blinnCase("light behind the surface, the half vector still toward the normal: "
                  "no specular without N . L > 0",
                  up, {-1, 0.6, 0}, 4, 5.0 * glm::normalize(dvec3(1, -0.2, 0))),
        blinnCase("one light in front, one behind the surface", up, {-1, 0.6, 0}, 4, {-2, 4, 1},
                  5.0 * glm::normalize(dvec3(1, -0.2, 0)), true),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const dvec3 normal = xyz(c.in[0]), toEye = xyz(c.in[1]);
        dvec3 color = kAmbient;
        const int lights = c.in[3].w > 0.0 ? 2 : 1;
        for (int i = 0; i < lights; ++i) {
            const dvec3 toLight = glm::normalize(xyz(c.in[std::size_t(2 + i)]));
            const reference::LightTerms t = reference::blinnPhongLight(
                normal, toEye, toLight, kLightColor[i], kDiffuse, kSpecular, c.in[0].w);
            color += t.diffuse + t.specular;
        }
        return dvec4(color, 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareColor(c, got, want, 2e-4);
    };
    return s;
}

// ---- 07 normal_map.glsl ----------------------------------------------------

// a0: the unit normal N; a1: the tangent (any length, not necessarily
// perpendicular to N); a2: the normal-map texel (0..1, encoded).
FunctionSpec applyNormalMapSpec() {
    FunctionSpec s;
    s.name = "applyNormalMap";
    s.prelude = RAYLAB_HARNESS_GLSL(
        "// A stand-in for the scene's textures: every lookup returns the case's texel.\n"
        "vec3 gCheckTexel;\n"
        "vec4 textureLayer(int layer, vec2 uv)\n"
        "{\n"
        "    return vec4(gCheckTexel, 1.0);\n"
        "}\n");
    s.includes = {"ray.glsl", "scene_materials.glsl", "surface.glsl", "normal_map.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL("vec4 checkApplyNormalMap(vec4 a0, vec4 a1, vec4 a2)\n"
                                    "{\n"
                                    "    gCheckTexel = a2.xyz;\n"
                                    "    Surface s;\n"
                                    "    s.point = vec3(0.0);\n"
                                    "    s.normal = a0.xyz;\n"
                                    "    s.tangent = a1.xyz;\n"
                                    "    s.uv = vec2(0.25, 0.75);\n"
                                    "    s.material.texture = -1;\n"
                                    "    s.material.normalMap = 0;\n"
                                    "    applyNormalMap(s);\n"
                                    "    return vec4(s.normal, 1.0);\n"
                                    "}\n");
    s.call = "checkApplyNormalMap(a0, a1, a2)";
    struct Row {
        const char* label;
        dvec3 normal, tangent, texel;
    } rows[] = {
        {"flat texel (0.5, 0.5, 1): the normal unchanged", {0, 0, 1}, {1, 0, 0}, {0.5, 0.5, 1.0}},
        {"texel leaning toward T (east)", {0, 0, 1}, {1, 0, 0}, {0.85, 0.5, 0.86}},
        {"texel leaning toward B (north)", {0, 0, 1}, {1, 0, 0}, {0.5, 0.85, 0.86}},
        {"tilted normal, perpendicular unit tangent",
         {0.6, 0.0, 0.8},
         {0.8, 0.0, -0.6},
         {0.3, 0.7, 0.9}},
        {"tangent of length 3 (normalise T)", {0, 1, 0}, {0, 0, -3}, {0.8, 0.3, 0.9}},
        {"tangent not perpendicular to N (remove its part along N)",
         {0, 1, 0},
         {0.8, 0.6, 0},
         {0.8, 0.3, 0.9}},
        {"tangent neither unit nor perpendicular to N",
         {0.3, 0.8, -0.5},
         {2.0, 1.5, 0.4},
         {0.25, 0.65, 0.85}},
        {"texel that decodes to a vector shorter than 1 (normalise the result)",
         {0, 0, 1},
         {0.9, 0.3, 0.7},
         {0.7, 0.4, 0.9}},
    };
    for (const Row& r : rows)
        s.cases.push_back(makeCase(
            std::string(r.label) + " [N " + caseVector(glm::normalize(r.normal)) + ", tangent " +
                caseVector(r.tangent) + ", texel " + caseVector(r.texel) + "]",
            dvec4(glm::normalize(r.normal), 0.0), dvec4(r.tangent, 0.0), dvec4(r.texel, 0.0)));
    for (FunctionCase& c : s.cases) c.uniforms = {{"uNormalMaps", 1}};
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(
            reference::applyNormalMap(xyz(c.in[0]), xyz(c.in[1]), xyz(c.in[2]) * 2.0 - 1.0), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) -> std::string {
        if (!allFinite(got)) return c.label + ": got NaN or Inf";
        std::string why = compareVector(c, got, want, 3, 1e-4);
        if (!why.empty() && std::fabs(glm::length(xyz(got)) - 1.0) > 1e-3)
            why += " (not of unit length: " + caseNumber(glm::length(xyz(got))) + ")";
        return why;
    };
    return s;
}

// ---- 08 color_mode.glsl ----------------------------------------------------

FunctionSpec applyColorModeSpec() {
    FunctionSpec s;
    s.name = "applyColorMode";
    s.includes = {"color_mode.glsl"};
    s.call = "vec4(applyColorMode(a0.xyz), 1.0)";
    const char* names[] = {"RGB", "BRB", "BRR", "RBB", "GGR"};
    for (int mode = 0; mode < 5; ++mode)
        for (const dvec3& color : {dvec3(0.1, 0.5, 0.9), dvec3(0.8, 0.3, 0.05)}) {
            FunctionCase c = makeCase("mode " + std::to_string(mode) + " (" + names[mode] +
                                          "), colour " + caseVector(color),
                                      dvec4(color, 0.0));
            c.uniforms = {{"uColorMode", mode}};
            s.cases.push_back(c);
        }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::applyColorMode(xyz(c.in[0]), c.uniforms.front().second), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 3, 1e-6);
    };
    return s;
}

// ---- 01 find_closest.glsl -------------------------------------------------

// a0: the ray's origin, a0.w the sphere count (1 or 2); a1: its unit
// direction; a2, a3: spheres 0 and 1 (centre, radius). The slot just past
// the count always holds a live sphere on the ray, nearer than any counted
// one: a loop that runs one step too far (i <= uSphereCount) finds it. The
// harness writes its slots at constant indices: Mesa's softpipe stores a
// write at a run-time index at one pixel's index for its whole 2x2 quad
// (docs/bench/README.md, "On Mesa's softpipe"), and wrote this decoy over
// sphere 1 of the neighbouring case.
FunctionCase closestCase(std::string label, dvec3 origin, dvec3 dir, int count, dvec4 sphere0,
                         dvec4 sphere1 = dvec4(0.0)) {
    return makeCase(std::move(label), dvec4(origin, count), dvec4(glm::normalize(dir), 0.0),
                    sphere0, sphere1);
}

FunctionSpec findClosestSpec() {
    FunctionSpec s;
    s.name = "findClosest";
    s.prelude = RAYLAB_HARNESS_GLSL("// Stand-ins for the scene's spheres, set by the case.\n"
                                    "int uSphereCount;\n"
                                    "vec4 uSpheres[MAX_SPHERES];\n");
    s.includes = {"ray.glsl", "intersect_sphere.glsl", "find_closest.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL(
        "vec4 checkFindClosest(vec4 a0, vec4 a1, vec4 a2, vec4 a3)\n"
        "{\n"
        "    uSphereCount = int(a0.w);  // 1 or 2\n"
        "    vec4 decoy = vec4(a0.xyz + 0.5 * a1.xyz, 0.2);  // just past the count: not counted\n"
        "    uSpheres[0] = a2;\n"
        "    uSpheres[1] = uSphereCount > 1 ? a3 : decoy;\n"
        "    uSpheres[2] = decoy;\n"
        "    Hit hit;\n"
        "    bool found = findClosest(Ray(a0.xyz, a1.xyz), hit);\n"
        "    return vec4(found ? 1.0 : 0.0, found ? hit.t : 0.0, float(hit.id), 1.0);\n"
        "}\n");
    s.call = "checkFindClosest(a0, a1, a2, a3)";
    const dvec3 back(0, 0, -1);
    s.cases = {
        closestCase("one sphere ahead (a sphere past the count sits nearer on the ray)", {0, 0, 5},
                    back, 1, {0, 0, 0, 1}),
        closestCase("two spheres, the second nearer", {0, 0, 5}, back, 2, {0, 0, -5, 1},
                    {0, 0, 0, 1}),
        closestCase("two spheres, the first nearer", {0, 0, 5}, back, 2, {0, 0, 0, 1},
                    {0, 0, -5, 1}),
        closestCase("two overlapping spheres: the nearer entry wins", {0, 0, 5}, back, 2,
                    {0, 0, 0, 1}, {0, 0, 0.5, 1}),
        closestCase("no counted sphere on the ray", {0, 0, 5}, back, 2, {5, 0, 0, 1},
                    {-5, 0, 0, 1}),
        closestCase("from inside sphere 0: its exit", {0, 0, 0}, {1, 0, 0}, 1, {0, 0, 0, 2}),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const dvec3 o = xyz(c.in[0]), d = xyz(c.in[1]);
        dvec4 best(0.0, 0.0, -1.0, 1.0);
        for (int i = 0; i < int(c.in[0].w); ++i) {
            const dvec4& sphere = c.in[std::size_t(2 + i)];
            const double t = reference::intersectSphere({o, d}, xyz(sphere), sphere.w);
            if (t != reference::kNoHit && (best.x == 0.0 || t < best.y))
                best = dvec4(1.0, t, i, 1.0);
        }
        return best;
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) -> std::string {
        auto text = [](const dvec4& v) {
            return v.x > 0.5 ? "sphere " + std::to_string(int(std::lround(v.z))) +
                                   " at t = " + caseNumber(v.y)
                             : std::string("no hit");
        };
        if (!allFinite(got)) return c.label + ": got NaN or Inf";
        const bool same = (got.x > 0.5) == (want.x > 0.5) &&
                          (want.x < 0.5 || (std::lround(got.z) == std::lround(want.z) &&
                                            std::fabs(got.y - want.y) <= 1e-4 * want.y));
        return same ? "" : c.label + ": expected " + text(want) + ", got " + text(got);
    };
    return s;
}

}  // namespace

std::vector<FunctionSpec> shadingFunctionSpecs() {
    return {findClosestSpec(), blinnPhongSpec(), applyNormalMapSpec(), applyColorModeSpec()};
}

}  // namespace raylab
