// The fur track's function checks from lab f2 on (shells, fins, strands):
// each GLSL function on a table of inputs against fur_reference.h /
// silhouette.h in double precision. Lab f1's are mesh_function_cases.cpp.
#include "fur_function_cases.h"

#include "adjacency.h"
#include "function_compare.h"
#ifndef RAYLAB_REFERENCES_AS_DATA  // the references: not in the page's core or a student build
#include "fur_reference.h"
#include "silhouette.h"
#endif
#include "mesh_shapes.h"

#include <cmath>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

// A float result within a relative 1e-5 (float gives about 1e-7).
std::string compareScalar(const FunctionCase& c, const dvec4& got, const dvec4& want) {
    return compareVector(c, got, want, 1, 1e-5 * std::max(1.0, std::fabs(want.x)));
}

std::string compareVec3(const FunctionCase& c, const dvec4& got, const dvec4& want) {
    return compareVector(c, got, want, 3, 1e-5 * std::max(1.0, glm::length(dvec3(want))));
}

// One row of a function of two numbers: its label and the numbers (a0.x, a0.y).
struct TwoNumbers {
    const char* label;
    double x, y;
};

// A function of two numbers with a scalar result: FUNCTION(a0.x, a0.y), or
// with ARGS as the GLSL arguments (shellLayer takes ints).
FunctionSpec twoNumberSpec(const char* name, const char* file, const std::string& args,
                           const std::vector<TwoNumbers>& rows,
                           [[maybe_unused]] double (*reference)(double, double)) {
    FunctionSpec s;
    s.name = name;
    s.includes = {file};
    s.call = "vec4(" + std::string(name) + "(" + args + "), 0.0, 0.0, 1.0)";
    for (const TwoNumbers& r : rows) s.cases.push_back(caseOf(r.label, dvec4(r.x, r.y, 0, 0)));
    RAYLAB_REFERENCE(s, [reference](const FunctionCase& c) {
        return dvec4(reference(c.in[0].x, c.in[0].y), 0, 0, 1);
    });
    s.compare = compareScalar;
    return s;
}

FunctionSpec shellLayerSpec() {
    return twoNumberSpec("shellLayer", "shell_layer.glsl", "int(a0.x), int(a0.y)",
                         {{"first of 30 draws: the skin", 0, 30},
                          {"second of 30", 1, 30},
                          {"middle of 30", 15, 30},
                          {"last of 30: the tips", 29, 30},
                          {"last of 2", 1, 2},
                          {"one shell: only the skin", 0, 1},
                          {"third of 4", 2, 4},
                          {"last of 256", 255, 256}},
                         RAYLAB_REFERENCE_FUNCTION([](double draw, double count) {
                             return fur_reference::shellLayer(int(draw), int(count));
                         }));
}

FunctionSpec shellAlphaSpec() {
    return twoNumberSpec("shellAlpha", "shell_alpha.glsl", "a0.x, a0.y",
                         {{"skin over a gap: opaque all the same", 0.0, 0.0},
                          {"skin under a hair", 0.8, 0.0},
                          {"a tall hair half way up", 1.0, 0.5},
                          {"a short hair near the root", 0.4, 0.1},
                          {"a gap half way up", 0.0, 0.5},
                          {"the tips: nothing left", 0.9, 1.0},
                          {"just above the skin", 0.6, 1.0 / 29.0}},
                         RAYLAB_REFERENCE_FUNCTION(fur_reference::shellAlpha));
}

FunctionSpec shellShadowSpec() {
    return twoNumberSpec("shellShadow", "shell_shadow.glsl", "a0.x, a0.y",
                         {{"skin, intensity 0.6", 0.0, 0.6},
                          {"tips, intensity 0.6", 1.0, 0.6},
                          {"half way, intensity 0.6", 0.5, 0.6},
                          {"no shadow at all", 0.3, 0.0},
                          {"full shadow at the skin", 0.0, 1.0},
                          {"a quarter up, intensity 0.3", 0.25, 0.3}},
                         RAYLAB_REFERENCE_FUNCTION(fur_reference::shellShadow));
}

FunctionSpec shellOffsetSpec() {
    FunctionSpec s;
    s.name = "shellOffset";
    s.includes = {"shell_offset.glsl"};
    s.call = "vec4(shellOffset(a0.xyz, a1.x, a1.y), 1.0)";
    const struct {
        const char* label;
        dvec3 normal;
        double layer, length;
    } rows[] = {{"skin: no offset", {0, 1, 0}, 0.0, 0.2},
                {"tips, normal up", {0, 1, 0}, 1.0, 0.2},
                {"half way, tilted normal", {0.6, 0.0, 0.8}, 0.5, 0.3},
                {"normal not unit length (3x)", {0, 0, 3}, 0.5, 0.2},
                {"short normal (0.01)", {0.01, 0, 0}, 1.0, 0.1},
                {"diagonal normal", {-1, 1, -1}, 0.25, 1.0}};
    for (const auto& r : rows)
        s.cases.push_back(caseOf(r.label, dvec4(r.normal, 0), dvec4(r.layer, r.length, 0, 0)));
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(fur_reference::shellOffset(dvec3(c.in[0]), c.in[1].x, c.in[1].y), 1);
    });
    s.compare = compareVec3;
    return s;
}

// A silhouette case: a0 = (A, eye.x), a1 = (B, eye.y), a2 = (C, eye.z), a3 = (D, 0).
FunctionCase edgeCase(std::string label, dvec3 eye, dvec3 a, dvec3 b, dvec3 c, dvec3 d) {
    FunctionCase f =
        caseOf(std::move(label), dvec4(a, eye.x), dvec4(b, eye.y), dvec4(c, eye.z), dvec4(d, 0.0));
#ifndef RAYLAB_REFERENCES_AS_DATA
    // Edge-on to either triangle: float may call it either way (a build
    // without the reference reads this from the tables: withHarnessFrom).
    f.hitOrMiss = silhouetteUncertain(eye, a, b, c, d);
#endif
    return f;
}

FunctionSpec silhouetteSpec() {
    FunctionSpec s;
    s.name = "isSilhouette";
    s.includes = {"silhouette.glsl"};
    s.call = "vec4(isSilhouette(vec3(a0.w, a1.w, a2.w), a0.xyz, a1.xyz, a2.xyz, a3.xyz) ? 1.0 : "
             "0.0, 0.0, 0.0, 1.0)";
    // A roof along x: B-C is the ridge, A on the -z slope, D on the +z slope
    // (both triangles counter-clockwise seen from above).
    const dvec3 b(0, 0, 0), c(1, 0, 0), a(0.5, -0.5, -1), d(0.5, -0.5, 1), flatD(0.5, 0, 1);
    const dvec3 flatA(0.5, 0, -1);
    s.cases = {
        edgeCase("roof seen from above: both faces toward the eye", {0.5, 5, 0}, a, b, c, d),
        edgeCase("roof seen from below: both faces away", {0.5, -5, 0}, a, b, c, d),
        edgeCase("roof seen from the -z side, low: one face each way", {0.5, -0.2, -5}, a, b, c, d),
        edgeCase("roof seen from the +z side, low: one face each way", {0.5, -0.2, 5}, a, b, c, d),
        edgeCase("flat edge seen from above", {0.3, 2, 0.4}, flatA, b, c, flatD),
        edgeCase("flat edge seen from below", {0.3, -2, 0.4}, flatA, b, c, flatD),
        edgeCase("boundary edge (D = A), seen from above", {0.5, 3, 0.2}, a, b, c, a),
        edgeCase("boundary edge (D = A), seen from below", {0.5, -3, 0.2}, a, b, c, a),
        edgeCase("degenerate triangle ABC (A on the edge's line)", {0.5, 0.2, -5}, {2, 0, 0}, b, c,
                 d),
        // The guide's contract: a zero normal makes the product 0, no fin,
        // even where the other triangle faces the eye (comparing the two
        // signs instead of testing the product's would stand a fin here).
        edgeCase("degenerate triangle ABC, BCD facing the eye", {0.5, 0.2, 5}, {2, 0, 0}, b, c, d),
        edgeCase("degenerate triangle BCD (D on the edge's line), ABC facing the eye",
                 {0.5, 0.2, -5}, a, b, c, {-1, 0, 0}),
        edgeCase("grazing: the eye in the plane of ABC", {0.5, -0.5 * 3, -3}, a, b, c, d),
        edgeCase("far away (1e3) on one side", {0.5, -200, -1000}, a, b, c, d),
        edgeCase("far away (1e3), both faces toward the eye", {0.5, 1000, 10}, a, b, c, d),
    };
    // A sphere's edges from several eyes: hundreds of ordinary cases.
    const Mesh sphere = makeShape("sphere", 6);
    const EdgeAdjacency adj = buildEdgeAdjacency(sphere);
    const dvec3 eyes[] = {{0, 0, 3}, {2.5, 1.0, 0.5}, {-0.3, -2.8, 1.1}};
    for (const dvec3& eye : eyes)
        for (std::size_t e = 0; e + 3 < adj.indices.size(); e += 4 * 7)
            s.cases.push_back(edgeCase("sphere edge " + std::to_string(e / 4) + " from (" +
                                           caseNumber(eye.x) + ", " + caseNumber(eye.y) + ", " +
                                           caseNumber(eye.z) + ")",
                                       eye, dvec3(sphere.positions[adj.indices[e]]),
                                       dvec3(sphere.positions[adj.indices[e + 1]]),
                                       dvec3(sphere.positions[adj.indices[e + 2]]),
                                       dvec3(sphere.positions[adj.indices[e + 3]])));
    RAYLAB_REFERENCE(s, [](const FunctionCase& row) {
        const dvec3 eye(row.in[0].w, row.in[1].w, row.in[2].w);
        return dvec4(silhouetteProduct(eye, dvec3(row.in[0]), dvec3(row.in[1]), dvec3(row.in[2]),
                                       dvec3(row.in[3])) < 0.0
                         ? 1.0
                         : 0.0,
                     0, 0, 1);
    });
    s.compare = [](const FunctionCase& row, const dvec4& got, const dvec4& want) -> std::string {
        if (!allFinite(got)) return row.label + ": got NaN or Inf";
        const bool g = got.x > 0.5, w = want.x > 0.5;
        if (g == w || row.hitOrMiss) return "";
        return row.label + ": expected " + (w ? "a silhouette" : "no silhouette") + ", got " +
               (g ? "a silhouette" : "none");
    };
    return s;
}

FunctionSpec strandPointSpec() {
    FunctionSpec s;
    s.name = "strandPoint";
    s.includes = {"strand_point.glsl"};
    s.call = "vec4(strandPoint(a0.xyz, a1.xyz, a2.x, a2.y, a3.xyz), 1.0)";
    const struct {
        const char* label;
        dvec3 root, normal;
        double at, length;
        dvec3 gravity;
    } rows[] = {
        {"the root", {1, 2, 3}, {0, 1, 0}, 0.0, 0.2, {0, -0.3, 0}},
        {"tip, no gravity", {0, 1, 0}, {0, 1, 0}, 1.0, 0.2, {0, 0, 0}},
        {"tip, drooping", {1, 0, 0}, {1, 0, 0}, 1.0, 0.2, {0, -0.4, 0}},
        {"half way: the bend grows with s squared", {1, 0, 0}, {1, 0, 0}, 0.5, 0.2, {0, -0.4, 0}},
        {"normal not unit length", {0, 0, 1}, {0, 0, 5}, 0.75, 0.1, {0, -0.3, 0}},
        {"hanging down from the bottom", {0, -1, 0}, {0, -1, 0}, 1.0, 0.3, {0, -0.3, 0}}};
    for (const auto& r : rows)
        s.cases.push_back(caseOf(r.label, dvec4(r.root, 0), dvec4(r.normal, 0),
                                 dvec4(r.at, r.length, 0, 0), dvec4(r.gravity, 0)));
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(fur_reference::strandPoint(dvec3(c.in[0]), dvec3(c.in[1]), c.in[2].x,
                                                c.in[2].y, dvec3(c.in[3])),
                     1);
    });
    s.compare = compareVec3;
    return s;
}

FunctionSpec kajiyaKaySpec() {
    FunctionSpec s;
    s.name = "kajiyaKay";
    s.includes = {"kajiya_kay.glsl"};
    s.call = "vec4(kajiyaKay(a0.xyz, a1.xyz, a2.xyz, a3.x), 0.0, 1.0)";
    const double r = std::sqrt(0.5);
    const struct {
        const char* label;
        dvec3 t, l, e;
        double shininess;
    } rows[] = {
        {"light and eye across the hair", {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 40},
        {"eye on the reflection cone", {1, 0, 0}, {r, r, 0}, {-r, 0, r}, 40},
        {"eye on the light's side of the cone: no highlight", {1, 0, 0}, {r, r, 0}, {r, r, 0}, 40},
        {"light along the hair: no light, and no NaN", {0, 1, 0}, {0, 1, 0}, {0, 0, 1}, 40},
        // A tangent normalised in float can come out 1 + 2^-23 long: then
        // (T . L)^2 > 1, and sqrt(1 - (T . L)^2) is NaN unless clamped.
        {"tangent a float ulp longer than 1, along the light",
         {1.00000012, 0, 0},
         {1, 0, 0},
         {0, 0, 1},
         40},
        {"tangent a float ulp longer than 1, along the eye",
         {0, 0, 1.00000012},
         {0, 1, 0},
         {0, 0, 1},
         40},
        {"eye along the hair", {0, 0, 1}, {1, 0, 0}, {0, 0, 1}, 40},
        // The eye along a tangent a float ulp too long, the light behind:
        // sin(T, E) must be clamped too, or NaN reaches the highlight.
        {"eye along a tangent an ulp longer than 1, light behind",
         {0, 0, 1.00000012},
         {0.8, 0, -0.6},
         {0, 0, 1},
         4},
        // The cone's cosine below zero: pow() of a negative number is NaN in
        // GLSL, so it must be clamped at 0 first.
        {"eye along the hair, light ahead: the cosine is negative",
         {1, 0, 0},
         {r, r, 0},
         {1, 0, 0},
         40},
        {"low shininess", {0.36, 0.48, 0.8}, {0, 1, 0}, {0.6, 0, 0.8}, 4},
    };
    for (const auto& w : rows)
        s.cases.push_back(caseOf(w.label, dvec4(w.t, 0), dvec4(w.l, 0), dvec4(w.e, 0),
                                 dvec4(w.shininess, 0, 0, 0)));
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(
            fur_reference::kajiyaKay(dvec3(c.in[0]), dvec3(c.in[1]), dvec3(c.in[2]), c.in[3].x), 0,
            1);
    });
    // pow(x, 40) multiplies the error of x by 40: 1e-4 still rejects a wrong formula.
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 2, 1e-4);
    };
    return s;
}

}  // namespace

std::vector<FunctionSpec> furFunctionSpecs() {
    return {shellLayerSpec(), shellOffsetSpec(), shellAlphaSpec(), shellShadowSpec(),
            silhouetteSpec(), strandPointSpec(), kajiyaKaySpec()};
}

}  // namespace raylab
