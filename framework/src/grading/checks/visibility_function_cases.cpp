// The function checks of lightVisible: lab 03's (the shadow ray from
// findClosest) and the full demo's (08: findBlocker, and no shadow ray to a
// light behind the surface). Both run in a scene of one or two spheres set
// from the case: the sphere the point lies on and a possible blocker.
#include "visibility_function_cases.h"

#include "case_patterns.h"
#include "function_compare.h"

#include <cmath>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

#ifndef RAYLAB_REFERENCES_AS_DATA
// The scene's lights (scene_lights.glsl) as globals the helper sets.
const char* kVisibilityLights = "// Stand-ins for the scene's lights, set by the case.\n"
                                "int uLightCount;\n"
                                "vec3 uLightPositions[MAX_LIGHTS];\n"
                                "vec3 uLightColors[MAX_LIGHTS];\n";
#endif

#ifndef RAYLAB_REFERENCES_AS_DATA
// Sets the light and the spheres from the case, calls lightVisible.
const char* kVisibilityHelper =
    "vec4 checkLightVisible(vec4 a0, vec4 a1, vec4 a2, vec4 a3)\n"
    "{\n"
    "    uLightCount = 1;\n"
    "    uLightPositions[0] = a2.xyz;\n"
    "    uLightColors[0] = vec3(1.0);\n"
    "    uSphereCount = 1;\n"
    "    uSpheres[0] = a3;\n"
    "    if (a0.w > 0.0) {\n"
    "        uSpheres[1] = vec4(mix(a0.xyz, a2.xyz, a1.w), a0.w);\n"
    "        uSphereCount = 2;\n"
    "    }\n"
    "    return vec4(lightVisible(a0.xyz, a1.xyz, 0) ? 1.0 : 0.0, 0.0, 0.0, 1.0);\n"
    "}\n";
#endif

// a0: the point, a0.w the radius of a blocking sphere (0: none); a1: the
// unit normal facing the eye, a1.w where the blocker's centre lies on the
// way from the point (0) to the light (1); a2: the light's position; a3 the
// sphere the point lies on (centre, radius).
FunctionCase visibilityCase(std::string label, dvec3 center, double radius, dvec3 outward,
                            bool eyeInside, dvec3 light, double blockerRadius = 0.0,
                            double blockerAt = 0.0) {
    const dvec3 out = glm::normalize(outward);
    label += " [point " + caseVector(center + radius * out) + ", normal " +
             caseVector(eyeInside ? -out : out) + ", light at " + caseVector(light) + "]";
    return caseOf(std::move(label), dvec4(center + radius * out, blockerRadius),
                  dvec4(eyeInside ? -out : out, blockerAt), dvec4(light, 0.0),
                  dvec4(center, radius));
}

// Does the open segment from P (on the sphere CENTER, RADIUS) to the light
// at distance DIST along the unit direction D cross a sphere?
[[maybe_unused]] bool crosses(const dvec3& p, const dvec3& d, double dist, const dvec3& center,
                              double radius, bool pointOnIt) {
    const dvec3 oc = p - center;
    const double b = glm::dot(oc, d);
    if (pointOnIt) {  // roots 0 and -2b: the other one is where the segment leaves or enters
        const double other = -2.0 * b;
        return other > 0.0 && other < dist;
    }
    const double h = b * b - (glm::dot(oc, oc) - radius * radius);
    if (h < 0.0) return false;
    const double t0 = -b - std::sqrt(h), t1 = -b + std::sqrt(h);
    return (t0 > 0.0 && t0 < dist) || (t1 > 0.0 && t1 < dist);
}

// The cases both stages share: lights in front of the point, blockers
// between and beyond, and points far from the origin.
std::vector<FunctionCase> sharedVisibilityCases() {
    const dvec3 o(0.0);
    std::vector<FunctionCase> cases = {
        visibilityCase("light above the point, nothing between", o, 1, {0, 1, 0}, false, {0, 5, 0}),
        visibilityCase("a sphere between the point and the light", o, 1, {0, 1, 0}, false,
                       {0, 5, 0}, 0.5, 0.5),
        visibilityCase("a sphere beyond the light", o, 1, {0, 1, 0}, false, {0, 5, 0}, 0.5, 1.5),
        visibilityCase("light on the far side of the point's own sphere", o, 1, {0, 1, 0}, false,
                       {0.5, -5, 0}),
        visibilityCase("grazing light, radius 100", o, 100, {0, 1, 0}, false, {400, 101, 0}),
        // The eye inside the sphere: the normal faces inward, the light is
        // outside - behind the surface seen from the eye.
        // (Labels say what the case is, not what a mistake would do: the
        // diagnoses below name causes, from the pattern of failing cases.)
        visibilityCase("eye inside a sphere of radius 100, light outside above the point", o, 100,
                       {0, 1, 0}, true, {30, 140, 0}),
        visibilityCase("eye outside a sphere of radius 100, light inside it", o, 100, {0, 1, 0},
                       false, {20, 30, 10}),
    };
    // Far from the origin float steps are large (1e-3 near 10^4, 8e-3 near
    // 10^5): a point computed there lies measurably above or below its
    // surface, and a shadow ray started on it, or a fixed 1e-3 off it, hits
    // its own sphere.
    struct Far {
        dvec3 center;
        double radius;
        const char* name;
    } far[] = {{{12000.0, -3000.0, 8000.0}, 5000.0, "radius 5000, 10^4 from the origin"},
               {{120000.0, -30000.0, 80000.0}, 50000.0, "radius 50000, 10^5 from the origin"},
               {{1.2e6, -3e5, 8e5}, 5e5, "radius 500000, 10^6 from the origin"}};
    for (const Far& f : far)
        for (int i = 0; i < 8; ++i) {
            const double a = 0.7 + 0.61 * i, z = -0.6 + 0.17 * i, r = std::sqrt(1.0 - z * z);
            const dvec3 outward(r * std::cos(a), z, r * std::sin(a));
            const dvec3 light = f.center + f.radius * outward +
                                0.8 * f.radius * glm::normalize(outward + dvec3(0.3, 0.5, -0.2));
            cases.push_back(visibilityCase(std::string("sphere of ") + f.name + ", point " +
                                               std::to_string(i + 1) + ", light in front",
                                           f.center, f.radius, outward, false, light));
        }
    return cases;
}

// Blocked by the point's own sphere or the blocker (lab 03's answer).
[[maybe_unused]] bool blockedBySpheres(const FunctionCase& c) {
    const dvec3 p = xyz(c.in[0]), toLight = xyz(c.in[2]) - p;
    const double dist = glm::length(toLight);
    const dvec3 d = toLight / dist;
    bool blocked = crosses(p, d, dist, xyz(c.in[3]), c.in[3].w, true);
    if (c.in[0].w > 0.0)
        blocked =
            blocked || crosses(p, d, dist, glm::mix(p, xyz(c.in[2]), c.in[1].w), c.in[0].w, false);
    return blocked;
}

std::string compareVisibility(const FunctionCase& c, const dvec4& got, const dvec4& want) {
    auto text = [](double v) { return v > 0.5 ? "visible" : "blocked"; };
    if (!allFinite(got)) return c.label + ": got NaN or Inf";
    if ((got.x > 0.5) == (want.x > 0.5)) return "";
    return c.label + ": expected the light " + text(want.x) + ", got " + text(got.x);
}

// What the pattern of failing cases proves about a shadow ray (lightVisible
// and 08's lightVisibleFast share the cases these read). First match wins.
std::vector<FunctionDiagnosis> shadowRayDiagnoses() {
    const CasePick open = labelStarts("light above the point, nothing between");
    const CasePick beyond = labelStarts("a sphere beyond the light");
    const CasePick grazing = labelStarts("grazing light");
    const CasePick far = labelHas(" from the origin, point ");
    const CasePick inside =
        either(either(labelStarts("eye inside a sphere"), labelStarts("eye outside a sphere")),
               labelStarts("eye and light inside a sphere"));
    return {
        {"beyond",
         "a sphere beyond the light blocks it, while a light with nothing between is "
         "visible: only a blocker nearer than the light may block it (compare the blocker's t "
         "with the distance to the light)",
         [=](const CaseVerdicts& v) { return anyFailed(v, beyond) && noneFailed(v, open); }},
        {"side",
         "a light with nothing between is blocked, a grazing one too: the shadow ray meets the "
         "point's own surface because it starts on the side away from the light; start it with "
         "offsetRayOrigin(point, side), side the normal when the light is in front of the "
         "surface, -normal when it is behind",
         [=](const CaseVerdicts& v) { return anyFailed(v, open) && anyFailed(v, grazing); }},
        {"direction",
         "a light with nothing between is blocked, though a grazing one is not: the shadow "
         "ray must go toward the light (the light's position minus the point, normalised), "
         "not away from it",
         [=](const CaseVerdicts& v) { return anyFailed(v, open) && noneFailed(v, grazing); }},
        {"far",
         "only points far from the origin (10^4 to 10^6) fail: there the shadow ray meets its "
         "own surface, as a fixed offset is too small for their float steps; "
         "offsetRayOrigin(point, side) grows with the point",
         [=](const CaseVerdicts& v) { return onlyFailed(v, far); }},
        {"own-surface",
         "the shadow ray meets its own surface at points far from the origin and inside large "
         "spheres, not at small ones: does it start off the surface, at "
         "offsetRayOrigin(point, side)?",
         [=](const CaseVerdicts& v) {
             return onlyFailed(v, either(far, inside)) && anyFailed(v, far) && anyFailed(v, inside);
         }},
        {"normal-side",
         "only where the eye or the light is inside a sphere (the light behind the surface the "
         "normal faces) is the light blocked: the shadow ray starts on the light's side, which "
         "is -normal there",
         [=](const CaseVerdicts& v) { return onlyFailed(v, inside); }},
    };
}

}  // namespace

FunctionSpec lightVisibilitySpec() {
    FunctionSpec s;
    s.name = "lightVisible";
    s.prelude = RAYLAB_HARNESS_GLSL(std::string(kVisibilityLights) +
                                    "// Stand-ins for the scene's spheres, set by the case.\n"
                                    "int uSphereCount;\n"
                                    "vec4 uSpheres[MAX_SPHERES];\n");
    s.includes = {"ray.glsl", "intersect_sphere.glsl", "find_closest.glsl",
                  "light_visibility.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL(kVisibilityHelper);
    s.call = "checkLightVisible(a0, a1, a2, a3)";
    s.cases = sharedVisibilityCases();
    const dvec3 o(0.0);
    // The side the shadow ray starts on, at sizes where the offset is longer
    // than T_MIN (a ray started on the wrong side then meets its own sphere):
    // the eye inside a sphere with a light outside, and a light inside a
    // sphere seen from outside.
    const struct {
        double radius;
        dvec3 outward;
    } sides[] = {{100.0, {0.3, 1.0, -0.2}},
                 {1000.0, {-0.5, 0.4, 0.7}},
                 {1e4, {0.8, -0.3, 0.4}},
                 {1e5, {-0.2, 0.6, -0.9}}};
    for (const auto& c : sides) {
        const dvec3 out = glm::normalize(c.outward);
        const std::string r = caseNumber(c.radius);
        s.cases.push_back(visibilityCase("eye inside a sphere of radius " + r +
                                             ", light outside in front of the point",
                                         o, c.radius, out, true, c.radius * (out * 1.6)));
        s.cases.push_back(visibilityCase(
            "eye outside a sphere of radius " + r + ", light inside it, behind the point", o,
            c.radius, out, false, c.radius * (0.3 * out + dvec3(0.1, -0.2, 0.15))));
    }
    for (FunctionCase& c : s.cases) c.uniforms = {{"uShadows", 1}};
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(blockedBySpheres(c) ? 0.0 : 1.0, 0.0, 0.0, 1.0);
    });
    s.compare = compareVisibility;
    s.diagnoses = shadowRayDiagnoses();
    return s;
}

// 08's lightVisible: the same question through findBlocker (provided by
// find_closest.glsl; here a stand-in over the case's spheres), and false
// without a shadow ray for a light behind the surface.
FunctionSpec lightVisibleFastSpec() {
    FunctionSpec s;
    s.name = "lightVisibleFast";
    s.prelude = RAYLAB_HARNESS_GLSL(
        std::string(kVisibilityLights) +
        "#include \"ray.glsl\"\n"
        "#include \"intersect_sphere.glsl\"\n"
        "// Stand-ins for the scene's spheres, set by the case, and for\n"
        "// find_closest.glsl's findBlocker over them.\n"
        "int uSphereCount;\n"
        "vec4 uSpheres[2];\n"
        "bool findBlocker(Ray ray, float maxT)\n"
        "{\n"
        "    for (int i = 0; i < uSphereCount; ++i) {\n"
        "        float t = intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w);\n"
        "        if (t != NO_HIT && t < maxT) return true;\n"
        "    }\n"
        "    return false;\n"
        "}\n");
    s.includes = {"light_visibility.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL(kVisibilityHelper);
    s.call = "checkLightVisible(a0, a1, a2, a3)";
    const dvec3 o(0.0);
    s.cases = sharedVisibilityCases();
    s.cases.push_back(caseOf("a light behind the surface: no shadow ray, not visible",
                             dvec4(0, 1, 0, 0), dvec4(0, 1, 0, 0), dvec4(3, -4, 1, 0),
                             dvec4(0, 0, 0, 1)));
    // The eye inside a big sphere and the light inside too, in front of the
    // point: the shadow ray starts on the normal's side, inside; started
    // outside it would cross the sphere.
    const struct {
        double radius;
        dvec3 outward;
    } inside[] = {{100.0, {0.3, 1.0, -0.2}}, {1e4, {0.8, -0.3, 0.4}}, {1e5, {-0.2, 0.6, -0.9}}};
    for (const auto& c : inside) {
        const dvec3 out = glm::normalize(c.outward);
        s.cases.push_back(visibilityCase("eye and light inside a sphere of radius " +
                                             caseNumber(c.radius) + ", the light in front",
                                         o, c.radius, out, true,
                                         c.radius * (0.3 * out + dvec3(0.1, -0.2, 0.15))));
    }
    for (FunctionCase& c : s.cases) c.uniforms = {{"uShadows", 1}};
    FunctionCase off = visibilityCase("shadows off (uShadows 0): visible behind a blocker", o, 1,
                                      {0, 1, 0}, false, {0, 5, 0}, 0.5, 0.5);
    off.uniforms = {{"uShadows", 0}};
    s.cases.push_back(off);
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const bool front = glm::dot(xyz(c.in[1]), xyz(c.in[2]) - xyz(c.in[0])) > 0.0;
        const bool visible = c.uniforms.at(0).second == 0 || (front && !blockedBySpheres(c));
        return dvec4(visible ? 1.0 : 0.0, 0.0, 0.0, 1.0);
    });
    s.compare = compareVisibility;
    s.diagnoses = shadowRayDiagnoses();
    return s;
}

}  // namespace raylab
