// The function checks of stage 06's sky and sun glow. The harness stands in
// for the scene with plain globals set from the case: the cube map as a
// function of the direction, and for the glow the sun sphere and "what
// findClosest finds first" as the case says, so no intersection code is
// involved and each case is exactly the situation its label names.
#include "sky_function_cases.h"

#include "function_compare.h"

#include "shader_constants.h"

#include <cmath>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

}  // namespace

// skyColor(dir): a0.xyz the direction (any length), a1.x 1 with a sky box,
// a2.xyz the background colour. The cube map stands in as a function of the
// direction (0.5 + 0.5 * the unit direction), read at level 0 with
// textureLod as the tracer reads every texture; any other lookup reads an
// empty cube map and fails with the colour it got.
FunctionSpec skyColorSpec() {
    FunctionSpec s;
    s.name = "skyColor";
    s.prelude = RAYLAB_HARNESS_GLSL(
        "// Stand-ins for the scene's sky, set by the case; the cube map is a function.\n"
        "int uHasSky;\n"
        "vec3 uBackground;\n"
        "uniform samplerCube uSky;\n"
        "vec4 checkSkyTexel(vec3 dir) { return vec4(0.5 + 0.5 * normalize(dir), 1.0); }\n"
        "#define textureLod(sampler, dir, level) checkSkyTexel(dir)\n");
    s.includes = {"sky.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL("vec4 checkSkyColor(vec4 a0, vec4 a1, vec4 a2)\n"
                                    "{\n"
                                    "    uHasSky = int(a1.x);\n"
                                    "    uBackground = a2.xyz;\n"
                                    "    return vec4(skyColor(a0.xyz), 1.0);\n"
                                    "}\n");
    s.call = "checkSkyColor(a0, a1, a2)";
    const dvec3 background(0.55, 0.7, 0.9);
    const struct {
        const char* label;
        dvec3 dir;
        bool sky;
    } rows[] = {
        {"sky box, straight up", {0, 1, 0}, true},
        {"sky box, toward -x", {-1, 0, 0}, true},
        {"sky box, a direction 3.7 long", {1.0, 2.0, 3.0}, true},
        {"sky box, down and back", {0.2, -0.9, -0.4}, true},
        {"no sky box: the background", {0, 1, 0}, false},
        {"no sky box, another direction", {0.6, -0.2, 0.77}, false},
    };
    for (const auto& r : rows) {
        FunctionCase c;
        c.label = r.label;
        c.in = {dvec4(r.dir, 0), dvec4(r.sky ? 1.0 : 0.0, 0, 0, 0), dvec4(background, 0),
                dvec4(0.0)};
        s.cases.push_back(c);
    }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return c.in[1].x > 0.5 ? dvec4(0.5 + 0.5 * glm::normalize(xyz(c.in[0])), 1.0)
                               : dvec4(xyz(c.in[2]), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 3, 1e-4);
    };
    return s;
}

// sunGlow(ray): a0.xyz the ray's origin, a0.w the sun's sphere index
// (uGlowSphere, -1: none); a1.xyz its unit direction, a1.w the halo's size
// in sun radii; a2 the sun (centre, radius); a3.x the distance of what
// findClosest finds first (< 0: nothing), a3.y its object id. Every other
// sphere index holds a decoy far away, so the wrong index shows.
FunctionSpec sunGlowSpec() {
    FunctionSpec s;
    s.name = "sunGlow";
    s.prelude =
        RAYLAB_HARNESS_GLSL("#include \"ray.glsl\"\n"
                            "#include \"scene_objects.glsl\"\n"
                            "// Stand-ins for the scene, set by the case: its spheres, the glow's\n"
                            "// settings, and the first thing on the ray.\n"
                            "vec4 uSpheres[MAX_SPHERES];\n"
                            "int uGlowSphere;\n"
                            "vec3 uGlowColor;\n"
                            "float uGlowSize;\n"
                            "Hit gFirstHit;\n"
                            "bool findClosest(Ray ray, out Hit hit)\n"
                            "{\n"
                            "    hit = gFirstHit;\n"
                            "    return hit.id >= 0;\n"
                            "}\n");
    s.includes = {"glow.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL(
        "vec4 checkSunGlow(vec4 a0, vec4 a1, vec4 a2, vec4 a3)\n"
        "{\n"
        "    for (int i = 0; i < MAX_SPHERES; ++i) uSpheres[i] = vec4(100.0, -80.0, 60.0, 0.5);\n"
        "    uGlowSphere = int(a0.w);\n"
        "    if (uGlowSphere >= 0) uSpheres[uGlowSphere] = a2;\n"
        "    uGlowColor = vec3(1.0, 0.8, 0.5);\n"
        "    uGlowSize = a1.w;\n"
        "    gFirstHit = Hit(T_FAR, -1);  // (no ?: on structures in WebGL)\n"
        "    if (a3.x >= 0.0) gFirstHit = Hit(a3.x, int(a3.y));\n"
        "    return vec4(sunGlow(Ray(a0.xyz, a1.xyz)), 1.0);\n"
        "}\n");
    s.call = "checkSunGlow(a0, a1, a2, a3)";
    const dvec4 sun(0.0, 3.0, -10.0, 1.0);
    const double other = double(shader::kPlane * shader::kObjectKindStride);  // a plane's id
    const struct {
        const char* label;
        dvec3 origin, toward;
        int glow;       // the sun's index, -1: no sun
        double size;    // halo size in sun radii
        double firstT;  // what findClosest finds first, < 0: nothing
        double firstId;
    } rows[] = {
        {"straight at the sun: full glow", {0, 0, 0}, {0, 3, -10}, 0, 2.0, 9.44, 0},
        {"aimed 1.5 radii beside the sun's centre, halo 2 radii",
         {0, 0, 0},
         {1.5, 3, -10},
         0,
         2.0,
         -1,
         0},
        {"aimed 2.2 radii beside the centre, halo 3 radii, sun at index 2",
         {0, 0, 0},
         {2.2, 3, -10},
         2,
         3.0,
         -1,
         0},
        {"outside the halo", {0, 0, 0}, {4.5, 3, -10}, 0, 2.0, -1, 0},
        {"the sun behind the eye", {0, 0, 0}, {-0.1, -0.3, 1}, 0, 2.0, -1, 0},
        {"no sun in the scene (uGlowSphere -1)", {0, 0, 0}, {0, 3, -10}, -1, 2.0, -1, 0},
        {"a plane in front of the sun's closest point",
         {0, 0, 0},
         {1.5, 3, -10},
         0,
         2.0,
         4.0,
         other},
        {"a plane behind the sun's closest point", {0, 0, 0}, {1.5, 3, -10}, 0, 2.0, 30.0, other},
        // Sphere 0 in front of a sun at another index: the blocker is the
        // sun only when its id is the sun's.
        {"sphere 0 in front of the sun (index 1)", {0, 0, 0}, {1.2, 3, -10}, 1, 2.0, 5.0, 0},
        {"sphere 0 in front of the sun (index 3), straight at it",
         {0, 0, 0},
         {0, 3, -10},
         3,
         2.0,
         3.0,
         0},
        {"sphere 0 just in front of the sun (index 2)", {0, 0, 0}, {0.5, 3, -10}, 2, 2.0, 9.0, 0},
        {"sphere 0 in front of the sun (index 1), another origin",
         {2, 1, 4},
         {-1.8, 2.1, -14},
         1,
         1.5,
         7.0,
         0},
        {"the ray from another origin, halo 1.5 radii", {2, 1, 4}, {-1.5, 2.1, -14}, 0, 1.5, -1, 0},
    };
    for (const auto& r : rows) {
        FunctionCase c;
        c.label = r.label;
        c.in = {dvec4(r.origin, r.glow), dvec4(glm::normalize(r.toward), r.size),
                dvec4(xyz(sun), sun.w), dvec4(r.firstT, r.firstId, 0, 0)};
        s.cases.push_back(c);
    }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const dvec3 o = xyz(c.in[0]), d = xyz(c.in[1]), center = xyz(c.in[2]);
        const double r = c.in[2].w;
        const int glow = int(c.in[0].w);
        if (glow < 0) return dvec4(0, 0, 0, 1);
        const double tc = glm::dot(center - o, d);
        if (tc < 0.0) return dvec4(0, 0, 0, 1);
        const double x = std::max(glm::length(o + tc * d - center) - r, 0.0) / (c.in[1].w * r);
        if (x >= 1.0) return dvec4(0, 0, 0, 1);
        const bool blocked = c.in[3].x >= 0.0 && int(c.in[3].y) != glow && c.in[3].x < tc;
        if (blocked) return dvec4(0, 0, 0, 1);
        return dvec4(dvec3(1.0, 0.8, 0.5) * std::pow(1.0 - x, 3.0), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 3, 1e-4);
    };
    return s;
}

}  // namespace raylab
