// The function-check tables and their double-precision references. The
// references follow the course's conventions exactly (T_MIN, NO_HIT = -1,
// which side counts), so any disagreement is the student's (or float's).
#include "bvh_function_cases.h"
#include "case_patterns.h"
#include "function_checks.h"
#include "function_compare.h"
#include "fur_function_cases.h"
#include "intersect_function_cases.h"
#include "mesh_function_cases.h"
#include "search_function_cases.h"
#include "shading_function_cases.h"
#include "sky_function_cases.h"
#include "trace_function_cases.h"
#include "visibility_function_cases.h"

#ifndef RAYLAB_REFERENCES_AS_DATA  // the references: not in the page's core or a student build
#include "reference_intersect.h"
#include "reference_shading.h"
#endif
#include "text_format.h"

#include "error.h"
#include "paths.h"

#include <cmath>
#include <cstdio>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

// 1 + 2^-23: a float step above 1, where a dot product of two unit vectors
// can land.
constexpr double kCosAboveOne = 1.0 + 1.0 / 8388608.0;

FunctionSpec fresnelDielectricSpec() {
    FunctionSpec s;
    s.name = "fresnelDielectric";
    s.includes = {"ray.glsl", "fresnel.glsl"};
    s.call = "vec4(fresnelDielectric(a0.x, a0.y), 0.0, 0.0, 1.0)";
    for (double ior : {1.33, 1.5, 2.4})
        for (double cosine : {1.0, 0.9, 0.6, 0.3, 0.1, 0.0}) {
            FunctionCase c;
            c.label = "ior " + caseNumber(ior) + ", cos " + caseNumber(cosine);
            c.in = {dvec4(cosine, ior, 0, 0), dvec4(0.0), dvec4(0.0), dvec4(0.0)};
            s.cases.push_back(c);
        }
    // The cosine of two unit vectors can round a float step above 1: pow()
    // of the negative 1 - cos is undefined in GLSL (NaN on Mesa).
    FunctionCase above;
    above.label = "ior 1.5, cos a float step above 1 (rounding): clamp 1 - cos before pow()";
    above.in = {dvec4(kCosAboveOne, 1.5, 0, 0), dvec4(0.0), dvec4(0.0), dvec4(0.0)};
    s.cases.push_back(above);
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::fresnelDielectric(c.in[0].x, c.in[0].y), 0, 0, 1);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        if (std::isfinite(got.x) && (got.x < 0.0 || got.x > 1.0))
            return c.label + ": F = " + caseNumber(got.x) +
                   " is not a share (reflected + transmitted must be 1, both >= 0)";
        return compareVector(c, got, want, 1, 1e-4);
    };
    return s;
}

FunctionSpec fresnelConductorSpec() {
    FunctionSpec s;
    s.name = "fresnelConductor";
    s.includes = {"ray.glsl", "fresnel.glsl"};
    s.call = "vec4(fresnelConductor(a0.x, a1.xyz, a2.xyz), 1.0)";
    const dvec3 goldN(0.143, 0.375, 1.442), goldK(3.983, 2.386, 1.603),
        silverN(0.155, 0.117, 0.135), silverK(4.83, 3.12, 2.15);
    for (double cosine : {1.0, 0.7, 0.4, 0.1, 0.0, kCosAboveOne}) {
        FunctionCase c;
        c.label = cosine > 1.0
                      ? "gold, cos a float step above 1 (rounding): clamp 1 - cos before pow()"
                      : "gold, cos " + caseNumber(cosine);
        c.in = {dvec4(cosine, 0, 0, 0), dvec4(goldN, 0), dvec4(goldK, 0), dvec4(0.0)};
        s.cases.push_back(c);
        c.label = cosine > 1.0 ? "silver, cos a float step above 1: clamp 1 - cos before pow()"
                               : "silver, cos " + caseNumber(cosine);
        c.in = {dvec4(cosine, 0, 0, 0), dvec4(silverN, 0), dvec4(silverK, 0), dvec4(0.0)};
        s.cases.push_back(c);
    }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::fresnelConductor(c.in[0].x, xyz(c.in[1]), xyz(c.in[2])), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 3, 1e-4);
    };
    return s;
}

// a0: the ray's unit direction; a1: the unit normal facing the ray; a2.x: 1
// entering the glass, 0 leaving it; a2.y: the index of refraction.
FunctionCase glassCase(const std::string& what, double degrees, bool entering, double ior) {
    const double a = glm::radians(degrees);
    const dvec3 normal(0, 1, 0), dir(std::sin(a), -std::cos(a), 0);
    FunctionCase c;
    c.label = what + " [" + (entering ? "entering" : "leaving") + ", ior " + caseNumber(ior) +
              ", " + caseNumber(degrees) + " degrees from the normal]";
    c.in = {dvec4(dir, 0), dvec4(normal, 0), dvec4(entering ? 1.0 : 0.0, ior, 0, 0), dvec4(0.0)};
    return c;
}

// What the pattern of refractGlass's failing cases proves. First match wins.
std::vector<FunctionDiagnosis> refractGlassDiagnoses() {
    const CasePick entering = [](const CaseVerdict& v) { return v.input->in[2].x > 0.5; };
    const CasePick notGlass = [](const CaseVerdict& v) { return v.input->in[2].y != 1.5; };
    const CasePick tir = [](const CaseVerdict& v) { return xyz(v.want) == dvec3(0.0); };
    // The refracted direction (or whether anything is refracted) is wrong,
    // not only F.
    const CasePick wrongWay = [](const CaseVerdict& v) {
        return (xyz(v.got) == dvec3(0.0)) != (xyz(v.want) == dvec3(0.0)) ||
               glm::length(xyz(v.got) - xyz(v.want)) > 1e-4;
    };
    return {
        {"ior",
         "only media other than glass go wrong (water 1.33, diamond 2.4), glass (1.5) is "
         "right: eta must come from the ior given, not a constant",
         [=](const CaseVerdicts& v) { return onlyFailed(v, notGlass); }},
        {"total-internal-reflection",
         "only total internal reflection goes wrong: there nothing is refracted and F is 1 "
         "(all of the light is reflected)",
         [=](const CaseVerdicts& v) { return onlyFailed(v, tir); }},
        {"eta",
         "only rays leaving the glass go the wrong way (entering ones are right): eta is the "
         "ratio of the indices from the ray's side to the other, 1/ior entering, ior leaving",
         [=](const CaseVerdicts& v) { return noneFailed(v, entering) && anyFailed(v, wrongWay); }},
        {"schlick-cosine",
         "leaving the glass only F is wrong, every direction is right: Schlick takes the cosine "
         "of the larger angle, on the air's side, which leaving is the refracted ray's",
         [=](const CaseVerdicts& v) { return noneFailed(v, entering) && noneFailed(v, wrongWay); }},
    };
}

FunctionSpec refractGlassSpec() {
    FunctionSpec s;
    s.name = "refractGlass";
    s.includes = {"ray.glsl", "fresnel.glsl"};
    s.call = "refractGlass(a0.xyz, a1.xyz, a2.x > 0.5, a2.y)";
    s.cases = {
        glassCase("head-on into glass", 0, true, 1.5),
        glassCase("into glass", 30, true, 1.5),
        glassCase("into glass, steep", 60, true, 1.5),
        glassCase("into glass, grazing", 85, true, 1.5),
        glassCase("into water", 45, true, 1.33),
        glassCase("into diamond", 45, true, 2.4),
        glassCase("out of glass, head-on", 0, false, 1.5),
        glassCase("out of glass", 30, false, 1.5),
        glassCase("out of glass, just below the critical angle 41.8", 41, false, 1.5),
        glassCase("out of glass beyond the critical angle: total internal reflection", 45, false,
                  1.5),
        glassCase("out of glass, grazing: total internal reflection", 80, false, 1.5),
        glassCase("out of water below its critical angle 48.8", 45, false, 1.33),
        glassCase("out of diamond below its critical angle 24.6", 20, false, 2.4),
        glassCase("out of diamond beyond the critical angle: total internal reflection", 30, false,
                  2.4),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return reference::refractGlass(xyz(c.in[0]), xyz(c.in[1]), c.in[2].x > 0.5, c.in[2].y);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) -> std::string {
        if (!allFinite(got)) return c.label + ": got NaN or Inf";
        const bool gotTir = xyz(got) == dvec3(0.0), wantTir = xyz(want) == dvec3(0.0);
        auto text = [](const dvec4& v) {
            return "refracted (" + caseNumber(v.x) + ", " + caseNumber(v.y) + ", " +
                   caseNumber(v.z) + "), F = " + caseNumber(v.w);
        };
        if (wantTir && !gotTir)
            return c.label +
                   ": expected total internal reflection (nothing refracted, F = 1), got " +
                   text(got);
        if (!wantTir && gotTir)
            return c.label + ": expected " + text(want) +
                   ", got total internal reflection (F = " + caseNumber(got.w) + ")";
        if (std::fabs(got.w - want.w) > 1e-4 || glm::length(xyz(got) - xyz(want)) > 1e-4)
            return c.label + ": expected " +
                   (wantTir ? "total internal reflection, F = 1" : text(want)) + ", got " +
                   (gotTir ? "F = " + caseNumber(got.w) : text(got));
        return "";
    };
    s.diagnoses = refractGlassDiagnoses();
    return s;
}

// u agrees modulo 1: the picture repeats (GL_REPEAT), so u and u + 1 are the
// same place, and at the seam u = 0 and u = 1 meet. A failure shows the
// values as returned.
std::string compareUv(const FunctionCase& c, const dvec4& got, const dvec4& want) {
    if (!allFinite(got)) return c.label + ": got NaN or Inf";
    dvec4 samePlace = got;
    samePlace.x -= std::round(got.x - want.x);
    if (compareVector(c, samePlace, want, 2, 1e-4).empty()) return "";
    std::string why = compareVector(c, got, want, 2, 1e-4);
    if (samePlace.x != got.x)
        why += " (u is compared modulo 1: u and u + 1 are the same place on the picture)";
    return why;
}

FunctionSpec sphereUvSpec() {
    FunctionSpec s;
    s.name = "sphereUV";
    s.includes = {"ray.glsl", "sphere_uv.glsl"};
    s.call = "vec4(sphereUV(a0.xyz), 0.0, 1.0)";
    const std::pair<const char*, dvec3> dirs[] = {
        {"+x (u = 0.5)", {1, 0, 0}},
        {"-z (east of +x)", {0, 0, -1}},
        {"+z", {0, 0, 1}},
        {"north pole", {0, 1, 0}},
        {"south pole", {0, -1, 0}},
        {"mid-latitude", {0.5, 0.6, -0.3}},
        {"southern", {-0.4, -0.7, 0.2}},
        {"near the seam", {-1, 0, 1e-3}},
        {"across the seam", {-1, 0, -1e-3}},
    };
    for (const auto& [label, d] : dirs) {
        FunctionCase c;
        c.label = label;
        c.in = {dvec4(glm::normalize(d), 0), dvec4(0.0), dvec4(0.0), dvec4(0.0)};
        s.cases.push_back(c);
    }
    // A unit vector computed in float can have |y| a float step above 1 at
    // a pole: asin() of it is undefined in GLSL (NaN on Mesa).
    for (double y : {kCosAboveOne, -kCosAboveOne}) {
        FunctionCase c;
        c.label = std::string(y > 0 ? "north" : "south") +
                  " pole, d.y a float step beyond 1 (rounding): clamp d.y before asin()";
        c.in = {dvec4(0, y, 0, 0), dvec4(0.0), dvec4(0.0), dvec4(0.0)};
        s.cases.push_back(c);
    }
    RAYLAB_REFERENCE(
        s, [](const FunctionCase& c) { return dvec4(reference::sphereUV(xyz(c.in[0])), 0, 1); });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        // At the poles every u is right.
        if (std::fabs(xyz(c.in[0]).y) > 1.0 - 1e-9)
            return compareVector(c, dvec4(got.y, 0, 0, 0), dvec4(want.y, 0, 0, 0), 1, 1e-4);
        return compareUv(c, got, want);
    };
    return s;
}

FunctionSpec planeUvSpec() {
    FunctionSpec s;
    s.name = "planeUV";
    s.includes = {"ray.glsl", "plane_uv.glsl"};
    s.call = "vec4(planeUV(a0.xyz, a1.xyz, a2.xyz, a2.w), 0.0, 1.0)";
    const dvec3 up(0, 1, 0), tilted = glm::normalize(dvec3(0.3, 0.2, 1.0));
    struct Row {
        const char* label;
        dvec3 point, origin, n;
        double tile;
    } rows[] = {
        {"floor, origin", {0, 0, 0}, {0, 0, 0}, up, 2.0},
        {"floor, one tile along x", {2, 0, 0}, {0, 0, 0}, up, 2.0},
        {"floor, along z", {0, 0, 3}, {0, 0, 0}, up, 2.0},
        {"floor, far away", {123, 0, -77}, {0, 0, 0}, up, 2.0},
        {"tile size 0.5", {1, 0, 1}, {0, 0, 0}, up, 0.5},
        {"tilted plane", {0.4, -0.3, 0.5}, {0.1, 0.1, 0.1}, tilted, 1.0},
    };
    for (const Row& r : rows) {
        FunctionCase c;
        c.label = r.label;
        c.in = {dvec4(r.point, 0), dvec4(r.origin, 0), dvec4(r.n, r.tile), dvec4(0.0)};
        s.cases.push_back(c);
    }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::planeUV(xyz(c.in[0]), xyz(c.in[1]), xyz(c.in[2]), c.in[2].w), 0, 1);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 2,
                             1e-4 * std::max(1.0, std::fabs(want.x) + std::fabs(want.y)));
    };
    return s;
}

}  // namespace

const std::vector<FunctionSpec>& functionSpecs() {
    static const std::vector<FunctionSpec> specs = [] {
        std::vector<FunctionSpec> all = {sphereSpec(),
                                         fresnelDielectricSpec(),
                                         fresnelConductorSpec(),
                                         refractGlassSpec(),
                                         traceSpec(),
                                         planeSpec(),
                                         discSpec(),
                                         triangleSpec(),
                                         torusNormalSpec(),
                                         torusQuarticSpec(),
                                         findClosestEveryKindSpec(),
                                         sphereUvSpec(),
                                         planeUvSpec(),
                                         skyColorSpec(),
                                         sunGlowSpec(),
                                         walkBvhSpec(),
                                         lightVisibilitySpec(),
                                         lightVisibleFastSpec()};
        for (FunctionSpec& f : shadingFunctionSpecs()) all.push_back(std::move(f));
        for (FunctionSpec& f : meshFunctionSpecs()) all.push_back(std::move(f));
        for (FunctionSpec& f : furFunctionSpecs()) all.push_back(std::move(f));
        return all;
    }();
    return specs;
}

const FunctionSpec& functionSpec(const std::string& name) {
    for (const FunctionSpec& s : functionSpecs())
        if (s.name == name) return s;
    std::string known;
    for (const FunctionSpec& s : functionSpecs()) known += (known.empty() ? "" : ", ") + s.name;
    throw Error("no function check '" + name + "' (known: " + known + ")");
}

std::vector<const FunctionSpec*> functionSpecsFor(const StageInfo& stage) {
    std::vector<const FunctionSpec*> out;
    for (std::size_t i = 0; i < stage.functionChecks.size(); ++i) {
        try {
            out.push_back(&functionSpec(stage.functionChecks[i]));
        } catch (const Error& e) {
            throw Error(displayPath(stage.folder() / "stage.json") + ": function_checks[" +
                        std::to_string(i) + "]: " + e.what());
        }
    }
    return out;
}

const StageInfo& stageCheckingFunction(const std::string& name) {
    for (const StageInfo& stage : allStages())
        for (const std::string& f : stage.functionChecks)
            if (f == name) return stage;
    throw Error("no stage lists the function check '" + name +
                "' (solution/*/stage.json, \"function_checks\")");
}

}  // namespace raylab
