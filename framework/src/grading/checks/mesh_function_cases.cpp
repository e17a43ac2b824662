// Lab f1's function checks (the lit mesh): the transforms, the normal matrix
// and the light, each on a table of inputs against double precision. The
// fur uniforms they read are plain variables in a function check
// (RAYLAB_FUNCTION_CHECK, fur_uniforms.glsl), set per case by the helpers.
#include "mesh_function_cases.h"

#include "function_compare.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

// normalMatrix(model) applied to a normal: a0..a2 the columns of the
// model's 3x3 part (w: its translation), a3 the normal. The result need not
// be unit length: its direction is checked.
FunctionSpec normalMatrixSpec() {
    FunctionSpec s;
    s.name = "normalMatrix";
    s.includes = {"normal_matrix.glsl"};
    s.call = "vec4(normalize(normalMatrix(mat4(vec4(a0.xyz, 0.0), vec4(a1.xyz, 0.0), "
             "vec4(a2.xyz, 0.0), vec4(a0.w, a1.w, a2.w, 1.0))) * a3.xyz), 1.0)";
    // A turn of 0.6 rad (34 degrees) about y.
    const glm::dmat3 turn(std::cos(0.6), 0, -std::sin(0.6), 0, 1, 0, std::sin(0.6), 0,
                          std::cos(0.6));
    const struct {
        const char* label;
        glm::dmat3 m;
        dvec3 move, normal;
    } rows[] = {
        {"identity", glm::dmat3(1.0), {0, 0, 0}, {0.6, 0.8, 0}},
        {"moved only: normals do not move", glm::dmat3(1.0), {5, -2, 3}, {0, 0, 1}},
        {"uniform scale 2.5", glm::dmat3(2.5), {0, 0, 0}, {0.36, 0.48, 0.8}},
        {"turned 34 degrees about y", turn, {1, 0, 0}, {1, 0, 0}},
        {"squashed: scale (1.5, 0.6, 1), the normal at 45 degrees",
         glm::dmat3(1.5, 0, 0, 0, 0.6, 0, 0, 0, 1),
         {0, 0, 0},
         {0.7071, 0.7071, 0}},
        {"squashed and turned",
         turn * glm::dmat3(1.5, 0, 0, 0, 0.6, 0, 0, 0, 1),
         {0.5, 1, -2},
         {0.48, 0.6, 0.64}},
        {"sheared", glm::dmat3(1, 0, 0, 0.8, 1, 0, 0, 0, 1), {0, 0, 0}, {0, 1, 0}},
        {"scale (3, 0.2, 0.5), a normal along no axis",
         glm::dmat3(3, 0, 0, 0, 0.2, 0, 0, 0, 0.5),
         {0, 0, 0},
         {0.2, 0.9, -0.3}},
    };
    for (const auto& r : rows)
        s.cases.push_back(caseOf(r.label, dvec4(r.m[0], r.move.x), dvec4(r.m[1], r.move.y),
                                 dvec4(r.m[2], r.move.z), dvec4(r.normal, 0.0)));
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const glm::dmat3 m(dvec3(c.in[0]), dvec3(c.in[1]), dvec3(c.in[2]));
        return dvec4(glm::normalize(glm::transpose(glm::inverse(m)) * dvec3(c.in[3])), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 3, 1e-4);
    };
    return s;
}

// surfaceLight(albedo, normal, toLight): a0 the albedo, a1 the normal (not
// always unit length: interpolated), a2 the unit direction toward the light,
// a3.xyz the light's colour and a3.w the ambient light (grey). The fur
// uniforms are plain variables in a function check (fur_uniforms.glsl).
FunctionSpec surfaceLightSpec() {
    FunctionSpec s;
    s.name = "surfaceLight";
    s.prelude = RAYLAB_HARNESS_GLSL("#define RAYLAB_FUNCTION_CHECK\n");
    s.includes = {"surface_light.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL("vec4 checkSurfaceLight(vec4 a0, vec4 a1, vec4 a2, vec4 a3)\n"
                                    "{\n"
                                    "    uLightColor = a3.xyz;\n"
                                    "    uAmbient = vec3(a3.w);\n"
                                    "    return vec4(surfaceLight(a0.xyz, a1.xyz, a2.xyz), 1.0);\n"
                                    "}\n");
    s.call = "checkSurfaceLight(a0, a1, a2, a3)";
    const dvec3 albedo(0.8, 0.5, 0.3), up(0, 1, 0), white(1.0);
    const struct {
        const char* label;
        dvec3 albedo, normal, toLight, color;
        double ambient;
    } rows[] = {
        {"light straight above", albedo, up, up, white, 0.2},
        {"light at 60 degrees", albedo, up, glm::normalize(dvec3(std::sqrt(3.0), 1, 0)), white,
         0.2},
        {"light behind the surface: ambient only", albedo, up, {0, -1, 0}, white, 0.2},
        {"grazing light (N . L = 0)", albedo, up, {1, 0, 0}, white, 0.15},
        {"an interpolated normal, 0.7 long", albedo, {0, 0.7, 0}, up, white, 0.1},
        {"an interpolated normal, 1.6 long and tilted",
         {0.4, 0.6, 0.9},
         {0.96, 1.28, 0},
         up,
         {1.0, 0.9, 0.8},
         0.18},
        {"coloured light, no ambient",
         {1, 1, 1},
         {0, 0, 1},
         glm::normalize(dvec3(0, 1, 1)),
         {0.9, 0.2, 0.1},
         0.0},
        {"black albedo", {0, 0, 0}, up, up, white, 0.3},
    };
    for (const auto& r : rows)
        s.cases.push_back(caseOf(r.label, dvec4(r.albedo, 0), dvec4(r.normal, 0),
                                 dvec4(r.toLight, 0), dvec4(r.color, r.ambient)));
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const dvec3 n = glm::normalize(dvec3(c.in[1]));
        const double lambert = std::max(glm::dot(n, dvec3(c.in[2])), 0.0);
        return dvec4(dvec3(c.in[0]) * (dvec3(c.in[3].w) + dvec3(c.in[3]) * lambert), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 3, 1e-5 * std::max(1.0, glm::length(dvec3(want))));
    };
    return s;
}

#ifndef RAYLAB_REFERENCES_AS_DATA  // a stand-in: the page's core and a student build read it from
                                   // the tables
// The GLSL that sets the fur uniforms of a transform check from the case:
// uModel = move a2.xyz, turn a1.x radians about y, scale a1.yzw; uView looks
// from a3.xyz turned a3.w radians about y; uProjection is a perspective of
// 45 degrees, aspect 4:3, near 0.1, far 100 (the column-major layout of
// glm::perspective).
const char* const kTransformHelpers =
    "void setTransforms(vec4 a1, vec4 a2, vec4 a3)\n"
    "{\n"
    "    float c = cos(a1.x), s = sin(a1.x);\n"
    "    mat4 turn = mat4(c, 0.0, -s, 0.0,  0.0, 1.0, 0.0, 0.0,  s, 0.0, c, 0.0,  0.0, 0.0, 0.0, "
    "1.0);\n"
    "    mat4 scale = mat4(a1.y, 0.0, 0.0, 0.0,  0.0, a1.z, 0.0, 0.0,  0.0, 0.0, a1.w, 0.0,  0.0, "
    "0.0, 0.0, 1.0);\n"
    "    mat4 move = mat4(1.0);\n"
    "    move[3] = vec4(a2.xyz, 1.0);\n"
    "    uModel = move * turn * scale;\n"
    "    float cv = cos(a3.w), sv = sin(a3.w);\n"
    "    mat4 view = mat4(cv, 0.0, sv, 0.0,  0.0, 1.0, 0.0, 0.0,  -sv, 0.0, cv, 0.0,  0.0, 0.0, "
    "0.0, 1.0);\n"
    "    mat4 back = mat4(1.0);\n"
    "    back[3] = vec4(-a3.xyz, 1.0);\n"
    "    uView = view * back;\n"
    "    float f = 1.0 / tan(radians(22.5));\n"
    "    uProjection = mat4(f / (4.0 / 3.0), 0.0, 0.0, 0.0,  0.0, f, 0.0, 0.0,  0.0, 0.0, "
    "-100.1 / 99.9, -1.0,  0.0, 0.0, -2.0 * 100.0 * 0.1 / 99.9, 0.0);\n"
    "}\n";
#endif

// The same matrices in double precision.
struct TransformCase {
    glm::dmat4 model, view, projection;
};
[[maybe_unused]] TransformCase transformsOf(const FunctionCase& c) {
    const dvec4 a1 = c.in[1], a2 = c.in[2], a3 = c.in[3];
    TransformCase t;
    t.model = glm::translate(glm::dmat4(1.0), dvec3(a2)) *
              glm::rotate(glm::dmat4(1.0), a1.x, dvec3(0, 1, 0)) *
              glm::scale(glm::dmat4(1.0), dvec3(a1.y, a1.z, a1.w));
    t.view = glm::rotate(glm::dmat4(1.0), -a3.w, dvec3(0, 1, 0)) *
             glm::translate(glm::dmat4(1.0), -dvec3(a3));
    t.projection = glm::perspective(glm::radians(45.0), 4.0 / 3.0, 0.1, 100.0);
    return t;
}

std::vector<FunctionCase> transformCases() {
    const struct {
        const char* label;
        dvec3 point;
        dvec4 turnScale;
        dvec3 move, eye;
        double yaw;
    } rows[] = {
        {"identity model, eye at (0, 0, 3)", {0.5, 0.25, 0}, {0, 1, 1, 1}, {0, 0, 0}, {0, 0, 3}, 0},
        {"moved by (1, -2, 0.5)", {0.2, 0.3, -0.1}, {0, 1, 1, 1}, {1, -2, 0.5}, {0, 0, 4}, 0},
        {"turned 30 degrees", {1, 0, 0}, {0.5236, 1, 1, 1}, {0, 0, 0}, {0.5, 0.2, 3}, 0.2},
        {"squashed (1.5, 0.6, 1) and moved",
         {0.3, 0.8, -0.4},
         {0.3, 1.5, 0.6, 1},
         {0, 1, 0},
         {-1, 1.5, 4},
         -0.3},
        {"scaled 2.5, eye turned 40 degrees",
         {-0.2, 0.1, 0.6},
         {-0.7, 2.5, 2.5, 2.5},
         {0.5, 0, -1},
         {2, 0.5, 3},
         0.7},
        {"a point behind the eye", {0, 0, 5}, {0, 1, 1, 1}, {0, 0, 0}, {0, 0, 3}, 0},
    };
    std::vector<FunctionCase> cases;
    for (const auto& r : rows)
        cases.push_back(caseOf(r.label, dvec4(r.point, 1.0), r.turnScale, dvec4(r.move, 0),
                               dvec4(r.eye, r.yaw)));
    return cases;
}

// A transform check: the case's matrices set (setTransforms), then
// EXPRESSION (of the point a0.xyz) against the reference, within TOLERANCE
// relative to its length.
FunctionSpec transformSpec(const char* name, [[maybe_unused]] const std::string& expression,
                           double tolerance) {
    FunctionSpec s;
    s.name = name;
    s.prelude = RAYLAB_HARNESS_GLSL("#define RAYLAB_FUNCTION_CHECK\n");
    s.includes = {"fur_uniforms.glsl", "transform.glsl"};
    s.helpers = RAYLAB_HARNESS_GLSL(std::string(kTransformHelpers) +
                                    "vec4 checkTransform(vec4 a0, vec4 a1, vec4 a2, vec4 a3)\n"
                                    "{\n"
                                    "    setTransforms(a1, a2, a3);\n"
                                    "    return " +
                                    expression +
                                    ";\n"
                                    "}\n");
    s.call = "checkTransform(a0, a1, a2, a3)";
    s.cases = transformCases();
    s.compare = [tolerance](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        return compareVector(c, got, want, 4, tolerance * std::max(1.0, glm::length(want)));
    };
    return s;
}

// toWorld(objectPoint): uModel * (p, 1).
FunctionSpec toWorldSpec() {
    FunctionSpec s = transformSpec("toWorld", "toWorld(a0.xyz)", 1e-5);
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return transformsOf(c).model * dvec4(dvec3(c.in[0]), 1.0);
    });
    return s;
}

// toClip(world): uProjection * uView * world, not divided by w.
FunctionSpec toClipSpec() {
    FunctionSpec s = transformSpec("toClip", "toClip(vec4(a0.xyz, 1.0))", 1e-4);
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const TransformCase t = transformsOf(c);
        return t.projection * t.view * dvec4(dvec3(c.in[0]), 1.0);
    });
    return s;
}
}  // namespace

std::vector<FunctionSpec> meshFunctionSpecs() {
    return {toWorldSpec(), toClipSpec(), normalMatrixSpec(), surfaceLightSpec()};
}

}  // namespace raylab
