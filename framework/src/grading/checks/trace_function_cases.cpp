// The function check of trace() (stage 04): the student's whole tracer - the
// loop, the stack, the depth limit, the weights and the sides secondary rays
// start on - run in small worlds of spheres, each case one primary ray,
// against a recursive tracer in double precision.
//
// What trace() calls comes from the harness: the student's own
// findClosest and Fresnel functions (checked by their own function checks),
// the framework's surfaceAt, and simple stand-ins for blinnPhong and skyColor
// (a colour that depends on the normal, the view and the direction, so that
// a normal not facing the ray, or a ray in the wrong direction, shows; they
// are not the lab's formulas, so the harness gives no solution away). The
// worlds are written once, here, and emitted as GLSL for the harness.
#include "trace_function_cases.h"

#include "case_patterns.h"
#include "function_compare.h"

#ifndef RAYLAB_REFERENCES_AS_DATA  // the references: not in the page's core or a student build
#include "reference_intersect.h"
#include "reference_shading.h"
#endif
#include "shader_constants.h"

#include <cmath>
#include <cstdio>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

enum MaterialType { kPlastic = 0, kMirror = 1, kGlass = 2, kMetal = 3 };  // MAT_* of the GLSL

struct WorldSphere {
    dvec3 center;
    double radius;
    int type;
    dvec3 diffuse;         // ambient is a tenth of it
    dvec3 specular{0.0};   // a mirror's reflectance
    double ior = 1.0;      // glass
    dvec3 n{1.0}, k{0.0};  // metal
};

struct World {
    const char* name;
    std::vector<WorldSphere> spheres;
};

const dvec3 kGoldN(0.143, 0.374, 1.442), kGoldK(3.983, 2.385, 1.603);

const std::vector<World>& worlds() {
    static const std::vector<World> all = {
        {"two mirrors facing each other",
         {{{0, 0, -22}, 20, kMirror, {0.1, 0.1, 0.1}, {0.8, 0.7, 0.6}},
          {{0, 0, 22}, 20, kMirror, {0.05, 0.1, 0.05}, {0.6, 0.75, 0.9}},
          {{0, -3, 0}, 1.5, kPlastic, {0.8, 0.3, 0.2}}}},
        {"a glass ball before a green wall and a mirror ball",
         {{{0, 0, -4}, 1, kGlass, {0.02, 0.02, 0.03}, {0.5, 0.5, 0.5}, 1.5},
          {{0, 0, -40}, 30, kPlastic, {0.2, 0.6, 0.3}},
          {{2.5, 0, -5}, 1, kMirror, {0.05, 0.05, 0.05}, {0.7, 0.7, 0.7}}}},
        {"inside a glass ball",
         {{{0, 0, 0}, 2, kGlass, {0.02, 0.03, 0.02}, {0.5, 0.5, 0.5}, 1.5},
          {{0, 0, -6}, 2, kPlastic, {0.7, 0.5, 0.2}},
          {{5, 0, 0}, 1, kPlastic, {0.2, 0.3, 0.8}}}},
        {"a gold ball beside a red one",
         {{{0, 0, -4}, 1, kMetal, {0.05, 0.04, 0.02}, dvec3(0.0), 1.0, kGoldN, kGoldK},
          {{2.2, 0, -4}, 1, kPlastic, {0.8, 0.2, 0.2}}}},
        {"two glass balls before a mirror, above a floor",
         {{{0, 0, -3}, 1, kGlass, {0.02, 0.02, 0.02}, {0.5, 0.5, 0.5}, 1.5},
          {{0.3, 0.2, -6}, 1.2, kGlass, {0.03, 0.02, 0.02}, {0.5, 0.5, 0.5}, 1.33},
          {{0, 0, -11}, 2, kMirror, {0.05, 0.05, 0.05}, {0.9, 0.85, 0.8}},
          {{0, -101.2, -5}, 100, kPlastic, {0.5, 0.5, 0.45}}}},
    };
    return all;
}

#ifndef RAYLAB_REFERENCES_AS_DATA
std::string glsl(const dvec3& v) {
    return "vec3(" + glslFloat(v.x) + ", " + glslFloat(v.y) + ", " + glslFloat(v.z) + ")";
}

// The worlds as GLSL: loadWorld(w, offset, scale) fills the stand-in spheres.
std::string traceWorldsGlsl() {
    std::string text = "void loadWorld(int world, vec3 offset, float scale)\n{\n"
                       "    gOffset = offset;\n    gScale = scale;\n    gSphereCount = 0;\n";
    for (std::size_t w = 0; w < worlds().size(); ++w) {
        text += std::string(w ? "    } else " : "    ") + "if (world == " + std::to_string(w) +
                ") {  // " + worlds()[w].name + "\n";
        for (const WorldSphere& s : worlds()[w].spheres)
            text += "        addSphere(" + glsl(s.center) + ", " + glslFloat(s.radius) +
                    ", Material(" + glsl(0.1 * s.diffuse) + ", " + glsl(s.diffuse) + ", " +
                    glsl(s.specular) + ", 32.0, " + std::to_string(s.type) + ", " +
                    glslFloat(s.ior) + ", " + glsl(s.n) + ", " + glsl(s.k) + ", -1, -1));\n";
    }
    return text + "    }\n}\n";
}

// ---- the stand-ins, in GLSL and in double ---------------------------------

// The most spheres a world has: the size of the stand-in materials. (A
// Material array of MAX_SPHERES tripled the harness's compile time in the
// page: WebGL zero-fills every global and the driver reads an array at a
// run-time index by choosing among all its entries. The spheres keep
// MAX_SPHERES, which a lab's loop may run to; a material is read only for a
// hit, whose index is below the world's count.)
std::size_t mostWorldSpheres() {
    std::size_t most = 0;
    for (const World& w : worlds()) most = std::max(most, w.spheres.size());
    return most;
}

std::string prelude() {
    return "#include \"ray.glsl\"\n"
           "#include \"scene_materials.glsl\"  // Material and MAT_*; the scene's uniforms go "
           "unused\n"
           "// Stand-ins for the scene, set by the case: the spheres findClosest reads\n"
           "// and each sphere's material.\n"
           "int gSphereCount;\n"
           "vec4 gSpheres[MAX_SPHERES];\n"
           "Material gMaterials[" +
           std::to_string(mostWorldSpheres()) + "];\n" +
           "#define uSphereCount gSphereCount\n"
           "#define uSpheres gSpheres\n"
           "#define materialOfSphere(i) gMaterials[i]\n"
           "#include \"intersect_sphere.glsl\"\n"
           "#include \"find_closest.glsl\"\n"
           "#include \"surface.glsl\"\n"
           "Surface surfaceAt(Ray ray, Hit hit)  // as the lab's surface_at.glsl\n"
           "{\n"
           "    vec4 s = gSpheres[hit.id];\n"
           "    vec3 outward = normalize(ray.origin + hit.t * ray.dir - s.xyz);\n"
           "    return Surface(s.xyz + s.w * outward, outward, gMaterials[hit.id], vec2(0.0), "
           "vec3(0.0));\n"
           "}\n"
           "// Stand-ins for the shading (not the lab's formulas): colours that depend\n"
           "// on the normal, the view and the direction.\n"
           "vec3 skyColor(vec3 dir)\n"
           "{\n"
           "    return vec3(0.35, 0.5, 0.75) + 0.25 * dir;\n"
           "}\n"
           "vec3 blinnPhong(vec3 point, vec3 normal, vec3 toEye, Material m)\n"
           "{\n"
           "    return m.ambient + m.diffuse * (0.25 + 0.75 * max(dot(normal, toEye), 0.0)) +\n"
           "           0.1 * m.specular * (0.5 + 0.5 * normal.y);\n"
           "}\n"
           "#include \"fresnel.glsl\"\n";
}

dvec3 skyStandIn(const dvec3& dir) { return dvec3(0.35, 0.5, 0.75) + 0.25 * dir; }

dvec3 blinnStandIn(const dvec3& normal, const dvec3& toEye, const WorldSphere& m) {
    return 0.1 * m.diffuse + m.diffuse * (0.25 + 0.75 * std::max(glm::dot(normal, toEye), 0.0)) +
           0.1 * m.specular * (0.5 + 0.5 * normal.y);
}
#endif

// a0: the primary ray's origin in world units, a0.w the world; a1: its unit
// direction; a2: the world's offset, a2.w its scale (origin and spheres are
// placed at offset + scale * position).
FunctionCase traceCase(int world, dvec3 origin, dvec3 toward, int maxDepth,
                       dvec3 offset = dvec3(0.0), double scale = 1.0) {
    const dvec3 dir = glm::normalize(toward);
    std::string label = std::string(worlds()[std::size_t(world)].name) + ", ray from (" +
                        caseNumber(origin.x) + ", " + caseNumber(origin.y) + ", " +
                        caseNumber(origin.z) + ") along (" + caseNumber(dir.x) + ", " +
                        caseNumber(dir.y) + ", " + caseNumber(dir.z) + "), uMaxDepth " +
                        std::to_string(maxDepth);
    if (scale != 1.0 || offset != dvec3(0.0))
        label += ", the world scaled by " + caseNumber(scale) + " and moved by (" +
                 caseNumber(offset.x) + ", " + caseNumber(offset.y) + ", " + caseNumber(offset.z) +
                 ")";
    FunctionCase c =
        caseOf(std::move(label), dvec4(origin, world), dvec4(dir, 0.0), dvec4(offset, scale));
    c.uniforms = {{"uMaxDepth", maxDepth}};
    return c;
}

#ifndef RAYLAB_REFERENCES_AS_DATA
struct Placed {
    dvec3 center;
    double radius;
    const WorldSphere* sphere;
};

// trace() as recursion, in double: the shading of every hit plus the
// reflected and refracted rays' colours weighted as the lab says.
dvec3 traceReference(const std::vector<Placed>& spheres, const reference::DRay& ray, int depth,
                     int maxDepth) {
    double t = reference::kNoHit;
    const Placed* hit = nullptr;
    for (const Placed& s : spheres) {
        const double ts = reference::intersectSphere(ray, s.center, s.radius);
        if (ts != reference::kNoHit && (hit == nullptr || ts < t)) t = ts, hit = &s;
    }
    if (hit == nullptr) return skyStandIn(ray.dir);
    const dvec3 outward = glm::normalize(ray.origin + t * ray.dir - hit->center);
    const dvec3 point = hit->center + hit->radius * outward;
    const bool entering = glm::dot(ray.dir, outward) < 0.0;
    const dvec3 normal = entering ? outward : -outward;
    const WorldSphere& m = *hit->sphere;
    dvec3 color = blinnStandIn(normal, -ray.dir, m);
    if (m.type == kPlastic || depth >= maxDepth) return color;
    const double cosIncident = -glm::dot(ray.dir, normal);
    dvec3 reflectance = m.specular;
    if (m.type == kMetal) reflectance = reference::fresnelConductor(cosIncident, m.n, m.k);
    if (m.type == kGlass) {
        const dvec4 glass = reference::refractGlass(ray.dir, normal, entering, m.ior);
        if (dvec3(glass) != dvec3(0.0))
            color += (1.0 - glass.w) *
                     traceReference(spheres, {point, dvec3(glass)}, depth + 1, maxDepth);
        reflectance = dvec3(glass.w);
    }
    return color + reflectance * traceReference(spheres, {point, glm::reflect(ray.dir, normal)},
                                                depth + 1, maxDepth);
}

dvec4 traceWant(const FunctionCase& c) {
    // The case's inputs as the harness reads them: rounded to float.
    const dvec4 a0 = asHarnessReads(c.in[0]), a1 = asHarnessReads(c.in[1]),
                a2 = asHarnessReads(c.in[2]);
    const dvec3 offset(a2);
    const double scale = a2.w;
    std::vector<Placed> spheres;
    for (const WorldSphere& s : worlds()[std::size_t(a0.w)].spheres)
        spheres.push_back({offset + scale * s.center, scale * s.radius, &s});
    return dvec4(traceReference(spheres, {offset + scale * dvec3(a0), dvec3(a1)}, 1,
                                c.uniforms.at(0).second),
                 1.0);
}
#endif

// What the pattern of trace's failing cases proves. First match wins.
std::vector<FunctionDiagnosis> traceDiagnoses() {
    const CasePick far = labelHas(", the world scaled by ");
    const CasePick mirrors = labelStarts("two mirrors facing each other");
    const CasePick gold = labelStarts("a gold ball");
    return {
        {"far",
         "only the worlds far from the origin go wrong (scaled by 10^4 to 10^5, moved 10^5 to "
         "10^6): there a reflected or refracted ray meets the surface it starts on; start "
         "each secondary ray with offsetRayOrigin (a fixed offset, or none, is too small "
         "there)",
         [=](const CaseVerdicts& v) { return onlyFailed(v, far); }},
        {"depth-limit",
         "between two mirrors the colour is the same whatever uMaxDepth is: a ray at the depth "
         "limit must not spawn secondary rays",
         [=](const CaseVerdicts& v) {
             // Two or more depths of the mirrors' ray wrong, all with one colour.
             const CaseVerdict* first = nullptr;
             int wrong = 0;
             for (const CaseVerdict& c : v) {
                 if (!c.failed || !mirrors(c) || far(c)) continue;
                 if (!first) first = &c;
                 if (glm::length(glm::dvec3(c.got) - glm::dvec3(first->got)) > 1e-4) return false;
                 ++wrong;
             }
             return wrong >= 2;
         }},
        {"glass",
         "only the worlds with glass go wrong (the mirrors and the gold are right): look at "
         "what glass adds, the refracted ray: where it starts (offsetRayOrigin on the far side "
         "of the surface, -normal), its weight (the path's weight times 1 - F, the reflected "
         "ray's times F) and the stack that keeps it until it is traced",
         [=](const CaseVerdicts& v) { return noneFailed(v, mirrors) && noneFailed(v, gold); }},
    };
}

}  // namespace

FunctionSpec traceSpec() {
    FunctionSpec s;
    s.name = "trace";
    s.prelude = RAYLAB_HARNESS_GLSL(prelude());
    s.includes = {"trace.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL(
        "vec3 gOffset;\n"
        "float gScale;\n"
        "void addSphere(vec3 center, float radius, Material m)\n"
        "{\n"
        "    gSpheres[gSphereCount] = vec4(gOffset + gScale * center, gScale * radius);\n"
        "    gMaterials[gSphereCount] = m;\n"
        "    ++gSphereCount;\n"
        "}\n" +
        traceWorldsGlsl() +
        "vec4 checkTrace(vec4 a0, vec4 a1, vec4 a2)\n"
        "{\n"
        "    loadWorld(int(a0.w), a2.xyz, a2.w);\n"
        "    return vec4(trace(Ray(a2.xyz + a2.w * a0.xyz, a1.xyz)), 1.0);\n"
        "}\n");
    s.call = "checkTrace(a0, a1, a2)";
    const dvec3 o(0.0);
    s.cases = {
        // The depth limit: each depth adds one reflection between the mirrors.
        traceCase(0, {0.1, 0.05, 0}, {0.02, 0.01, -1}, 1),
        traceCase(0, {0.1, 0.05, 0}, {0.02, 0.01, -1}, 2),
        traceCase(0, {0.1, 0.05, 0}, {0.02, 0.01, -1}, 3),
        traceCase(0, {0.1, 0.05, 0}, {0.02, 0.01, -1}, 5),
        traceCase(0, {0.1, 0.05, 0}, {0.02, 0.01, -1}, 8),
        traceCase(0, {0.1, 0.05, 0}, {0.0, -0.4, -1}, 8),
        // Glass: a reflected and a refracted ray at every surface.
        traceCase(1, o, {0, 0, -1}, 2),
        traceCase(1, o, {0, 0, -1}, 8),
        traceCase(1, o, {0.5, 0.3, -4}, 3),
        traceCase(1, o, {0.5, 0.3, -4}, 8),
        traceCase(1, o, {0.85, 0, -4}, 8),
        // From inside: leaving the glass, and total internal reflection.
        traceCase(2, {0.5, 0.2, 0}, {0, 0, -1}, 8),
        traceCase(2, {1.5, 0, 0}, {0, 0, -1}, 2),
        traceCase(2, {1.5, 0, 0}, {0, 0, -1}, 8),
        traceCase(2, o, {1, 0.1, 0}, 8),
        // Just under the critical angle a third of the light stays inside at
        // every bounce, and every bounce leaves a refracted ray waiting.
        traceCase(2, {1.3, 0, 0}, {0, 0, -1}, 8),
        traceCase(2, {0, 1.28, 0.5}, {0, 0, -1}, 8),
        traceCase(2, {-0.9, 0.95, 0}, {0, 0, -1}, 8),
        // Metal: Fresnel per channel.
        traceCase(3, o, {0, 0, -1}, 1),
        traceCase(3, o, {0, 0, -1}, 8),
        traceCase(3, o, {0.5, 0.2, -4}, 8),
        traceCase(3, o, {0.8, 0, -4}, 8),
        // Many branches: the stack holds several waiting rays.
        traceCase(4, {0, 0.3, 0}, {0.05, -0.05, -1}, 8),
        traceCase(4, {0.1, 0.1, 0}, {0, 0, -1}, 4),
        traceCase(4, {0.1, 0.1, 0}, {0, 0, -1}, 8),
    };
    // Far from the origin a secondary ray's offset is longer than T_MIN: a
    // ray started on the wrong side meets the surface it leaves.
    const struct {
        dvec3 offset;
        double scale;
    } far[] = {{{1e5 + 0.35, -3e4 + 0.7, 7e4 + 0.2}, 1e4},
               {{-1e6 + 0.35, 2e5 + 0.4, -6e5 + 0.1}, 1e5}};
    for (const auto& f : far) {
        s.cases.push_back(traceCase(1, o, {0.5, 0.3, -4}, 8, f.offset, f.scale));
        s.cases.push_back(traceCase(2, {0.5, 0.2, 0}, {0, 0, -1}, 8, f.offset, f.scale));
        s.cases.push_back(traceCase(2, {1.5, 0, 0}, {0, 0, -1}, 8, f.offset, f.scale));
        s.cases.push_back(traceCase(2, {1.3, 0, 0}, {0, 0, -1}, 8, f.offset, f.scale));
        s.cases.push_back(traceCase(4, {0.1, 0.1, 0}, {0, 0, -1}, 8, f.offset, f.scale));
    }
    RAYLAB_REFERENCE(s, traceWant);
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        const double scale =
            std::max({1.0, std::fabs(want.x), std::fabs(want.y), std::fabs(want.z)});
        return compareVector(c, got, want, 3, 2e-3 * scale);
    };
    s.diagnoses = traceDiagnoses();
    return s;
}

}  // namespace raylab
