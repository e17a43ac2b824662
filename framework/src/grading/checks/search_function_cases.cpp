// Stage 05's findClosest: the nearest hit over spheres, planes, discs,
// triangles and tori, with each hit's object id. The check is about the
// search alone, so the harness replaces the intersection functions with
// stand-ins that return a distance the case chooses: each object's data
// (centre, normal, offset, radius, corners) adds up to it, so the
// stand-in returns the right distance only when findClosest passes that
// object's own data. (No intersection formula is in the harness: nothing
// of lab 01's or 05's answers is handed out with it.)
#include "search_function_cases.h"

#include "function_compare.h"

#include "shader_constants.h"

#include <cmath>
#include <iterator>

namespace raylab {

namespace {

using glm::dvec4;

// Up to two objects of each kind, in the order findClosest visits the kinds.
constexpr int kKinds = 5;
[[maybe_unused]] constexpr shader::ObjectKind kKindOrder[kKinds] = {
    shader::kSphere, shader::kPlane, shader::kDisc, shader::kTriangle, shader::kTorus};

// What a case sets: each kind's count (0..2) and the distance each of its
// two objects answers (-1: the ray misses it). Objects past a count answer
// 0.5, nearer than every counted one: a loop that runs past a count finds
// one of them.
struct Objects {
    int count[kKinds];
    double t[kKinds][2];
};

// a0: the spheres' and the planes' distances; a1: the discs' and the
// triangles'; a2: the tori's, a2.z unused, a2.w the torus count; a3: the
// counts of spheres, planes, discs and triangles.
FunctionCase searchCase(std::string label, const Objects& o) {
    return caseOf(std::move(label), dvec4(o.t[0][0], o.t[0][1], o.t[1][0], o.t[1][1]),
                  dvec4(o.t[2][0], o.t[2][1], o.t[3][0], o.t[3][1]),
                  dvec4(o.t[4][0], o.t[4][1], 0.0, o.count[4]),
                  dvec4(o.count[0], o.count[1], o.count[2], o.count[3]));
}

[[maybe_unused]] Objects objectsOf(const FunctionCase& c) {
    Objects o{};
    const double t[kKinds][2] = {{c.in[0].x, c.in[0].y},
                                 {c.in[0].z, c.in[0].w},
                                 {c.in[1].x, c.in[1].y},
                                 {c.in[1].z, c.in[1].w},
                                 {c.in[2].x, c.in[2].y}};
    const double count[kKinds] = {c.in[3].x, c.in[3].y, c.in[3].z, c.in[3].w, c.in[2].w};
    for (int k = 0; k < kKinds; ++k) {
        o.count[k] = int(count[k]);
        o.t[k][0] = t[k][0];
        o.t[k][1] = t[k][1];
    }
    return o;
}

#ifndef RAYLAB_REFERENCES_AS_DATA
const char* kSearchPrelude =
    "#include \"ray.glsl\"\n"
    "#include \"scene_spheres.glsl\"\n"
    "#include \"scene_objects.glsl\"  // objectId and KIND_*; the scene's uniforms go unused\n"
    "// Stand-ins for the scene's objects, set by the case.\n"
    "int gSphereCount, gPlaneCount, gDiscCount, gTriangleCount, gTorusCount;\n"
    "vec4 gSpheres[MAX_SPHERES];\n"
    "vec4 gPlanes[MAX_PLANES];\n"
    "vec4 gDiscs[MAX_DISCS];\n"
    "vec3 gDiscNormals[MAX_DISCS];\n"
    "vec3 gTriangleVertices[3 * MAX_TRIANGLES];\n"
    "float gTorusT[MAX_TORI];\n"
    "#define uSphereCount gSphereCount\n"
    "#define uSpheres gSpheres\n"
    "#define uPlaneCount gPlaneCount\n"
    "#define uPlanes gPlanes\n"
    "#define uDiscCount gDiscCount\n"
    "#define uDiscs gDiscs\n"
    "#define uDiscNormals gDiscNormals\n"
    "#define uTriangleCount gTriangleCount\n"
    "#define uTriangleVertices gTriangleVertices\n"
    "#define uTorusCount gTorusCount\n"
    "// Stand-ins for the intersections: the distance the case chose for the\n"
    "// object whose data is passed (its numbers add up to it).\n"
    "float sum3(vec3 v) { return v.x + v.y + v.z; }\n"
    "float intersectSphere(Ray ray, vec3 center, float radius) { return sum3(center) + radius; }\n"
    "float intersectPlane(Ray ray, vec3 normal, float offset) { return sum3(normal) + offset; }\n"
    "float intersectDisc(Ray ray, vec3 center, vec3 normal, float radius)\n"
    "{\n"
    "    return sum3(center) + sum3(normal) + radius;\n"
    "}\n"
    "float intersectTriangle(Ray ray, vec3 a, vec3 b, vec3 c) { return sum3(a + b + c); }\n"
    "float intersectTorus(Ray ray, int i) { return gTorusT[i]; }\n";
#endif

#ifndef RAYLAB_REFERENCES_AS_DATA
const char* kHelpers =
    "void setObject(int kind, int i, float t)\n"
    "{\n"
    "    if (kind == KIND_SPHERE) gSpheres[i] = vec4(t - 0.75, 0.25, 0.25, 0.25);\n"
    "    if (kind == KIND_PLANE) gPlanes[i] = vec4(0.125, 0.25, 0.125, t - 0.5);\n"
    "    if (kind == KIND_DISC) {\n"
    "        gDiscs[i] = vec4(t - 1.0, 0.25, 0.25, 0.125);\n"
    "        gDiscNormals[i] = vec3(0.125);\n"
    "    }\n"
    "    if (kind == KIND_TRIANGLE) {\n"
    "        gTriangleVertices[3 * i] = vec3(t - 1.5, 0.25, 0.25);\n"
    "        gTriangleVertices[3 * i + 1] = vec3(0.25, 0.25, 0.0);\n"
    "        gTriangleVertices[3 * i + 2] = vec3(0.25, 0.0, 0.25);\n"
    "    }\n"
    "    if (kind == KIND_TORUS) gTorusT[i] = t;\n"
    "}\n"
    "void setKind(int kind, int count, float t0, float t1)\n"
    "{\n"
    "    for (int i = 0; i < 3; ++i)  // past the count: nearer than every counted one\n"
    "        if (kind != KIND_TORUS || i < MAX_TORI) setObject(kind, i, 0.5);\n"
    "    setObject(kind, 0, count > 0 ? t0 : 0.5);\n"
    "    setObject(kind, 1, count > 1 ? t1 : 0.5);\n"
    "}\n"
    "vec4 checkFindClosest(vec4 a0, vec4 a1, vec4 a2, vec4 a3)\n"
    "{\n"
    "    gSphereCount = int(a3.x);\n"
    "    gPlaneCount = int(a3.y);\n"
    "    gDiscCount = int(a3.z);\n"
    "    gTriangleCount = int(a3.w);\n"
    "    gTorusCount = int(a2.w);\n"
    "    setKind(KIND_SPHERE, gSphereCount, a0.x, a0.y);\n"
    "    setKind(KIND_PLANE, gPlaneCount, a0.z, a0.w);\n"
    "    setKind(KIND_DISC, gDiscCount, a1.x, a1.y);\n"
    "    setKind(KIND_TRIANGLE, gTriangleCount, a1.z, a1.w);\n"
    "    setKind(KIND_TORUS, gTorusCount, a2.x, a2.y);\n"
    "    Hit hit;\n"
    "    bool found = findClosest(Ray(vec3(0.0), vec3(0.0, 0.0, -1.0)), hit);\n"
    "    return vec4(found ? 1.0 : 0.0, found ? hit.t : 0.0, float(hit.id), 1.0);\n"
    "}\n";
#endif

std::string objectHitText(const dvec4& v) {
    if (v.x < 0.5) return "no hit";
    const long id = std::lround(v.z);
    const long kind = id / shader::kObjectKindStride, index = id % shader::kObjectKindStride;
    const std::string name = kind >= 0 && kind < long(std::size(shader::kKindNames))
                                 ? shader::kKindNames[kind]
                                 : "object";
    return name + " " + std::to_string(index) + " (id " + std::to_string(id) +
           ") at t = " + caseNumber(v.y);
}

}  // namespace

FunctionSpec findClosestEveryKindSpec() {
    FunctionSpec s;
    s.name = "findClosestEveryKind";
    s.prelude = RAYLAB_HARNESS_GLSL(kSearchPrelude);
    s.includes = {"find_closest.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL(kHelpers);
    s.call = "checkFindClosest(a0, a1, a2, a3)";
    const double miss = -1.0;  // NO_HIT
    s.cases = {
        searchCase("a sphere only", {{1, 0, 0, 0, 0}, {{3.5, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}}),
        searchCase("a plane nearer than a sphere",
                   {{1, 1, 0, 0, 0}, {{3.5, 0}, {2.25, 0}, {0, 0}, {0, 0}, {0, 0}}}),
        searchCase("disc 1 nearest, one of each kind but tori",
                   {{1, 1, 2, 1, 0}, {{3.5, 0}, {4.0, 0}, {5.0, 1.75}, {6.0, 0}, {0, 0}}}),
        searchCase("triangle 1 nearest (its corners are 3, 4 and 5)",
                   {{2, 1, 1, 2, 1}, {{3.5, 6.5}, {4.0, 0}, {5.0, 0}, {7.0, 1.25}, {8.0, 0}}}),
        searchCase("torus 1 nearest",
                   {{2, 2, 2, 2, 2}, {{3.5, 6.5}, {4.0, 9}, {5.0, 4.5}, {7.0, 3.25}, {8.0, 2.75}}}),
        searchCase("sphere 1 nearest of every kind",
                   {{2, 2, 2, 2, 2}, {{3.5, 1.5}, {4.0, 9}, {5.0, 4.5}, {7.0, 3.25}, {8.0, 2.75}}}),
        searchCase("plane 1 nearest; the nearer sphere misses (NO_HIT is not a distance)",
                   {{2, 2, 0, 0, 0}, {{miss, 6.5}, {4.0, 2.5}, {0, 0}, {0, 0}, {0, 0}}}),
        searchCase("everything misses",
                   {{2, 2, 2, 2, 2},
                    {{miss, miss}, {miss, miss}, {miss, miss}, {miss, miss}, {miss, miss}}}),
        searchCase("no objects at all",
                   {{0, 0, 0, 0, 0}, {{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}}),
        searchCase("only tori, torus 0 nearer",
                   {{0, 0, 0, 0, 2}, {{0, 0}, {0, 0}, {0, 0}, {0, 0}, {1.75, 3.5}}}),
        searchCase("a disc nearest, the triangles miss",
                   {{1, 0, 1, 2, 0}, {{6.0, 0}, {0, 0}, {2.5, 0}, {miss, miss}, {0, 0}}}),
        searchCase("the last kind's miss does not clear an earlier hit",
                   {{1, 1, 1, 1, 1}, {{6.0, 0}, {5.0, 0}, {2.5, 0}, {3.5, 0}, {miss, 0}}}),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const Objects o = objectsOf(c);
        dvec4 best(0.0, 0.0, -1.0, 1.0);
        for (int k = 0; k < kKinds; ++k)
            for (int i = 0; i < o.count[k]; ++i) {
                const double t = o.t[k][i];
                if (t != shader::kNoHit && (best.x == 0.0 || t < best.y))
                    best = dvec4(1.0, t, kKindOrder[k] * shader::kObjectKindStride + i, 1.0);
            }
        return best;
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) -> std::string {
        if (!allFinite(got)) return c.label + ": got NaN or Inf";
        const bool same = (got.x > 0.5) == (want.x > 0.5) &&
                          (want.x < 0.5 || (std::lround(got.z) == std::lround(want.z) &&
                                            std::fabs(got.y - want.y) <= 1e-6 * want.y));
        return same ? ""
                    : c.label + ": expected " + objectHitText(want) + ", got " + objectHitText(got);
    };
    return s;
}

}  // namespace raylab
