// The function-check tables of the intersection routines (stages 01, 05):
// sphere, plane, disc, triangle and the torus's normal, with their
// double-precision references (the reference tracer's own,
// reference_intersect.h) and the hard cases each must get right.
#include "intersect_function_cases.h"

#include "function_compare.h"
#include "shader_constants.h"

#ifndef RAYLAB_REFERENCES_AS_DATA  // the references: not in the page's core or a student build
#include "reference_intersect.h"
#endif

#include <cmath>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

using shader::kNoHit;

std::string hitText(double t) { return t < 0.0 ? "no hit" : "t = " + caseNumber(t); }

// Hit distances: hit or miss must agree (unless on the boundary), t within a
// relative 1e-4 - float32 gives about 1e-7, a wrong formula far more.
std::string compareHit(const FunctionCase& c, const dvec4& got, const dvec4& want) {
    if (!allFinite(got)) return c.label + ": expected " + hitText(want.x) + ", got NaN or Inf";
    bool gotHit = got.x != kNoHit, wantHit = want.x != kNoHit;
    if (gotHit && got.x <= 0.0)
        return c.label + ": returned t = " + caseNumber(got.x) +
               ", neither a hit in front of the ray nor NO_HIT";
    if (gotHit != wantHit) {
        if (c.hitOrMiss && !gotHit) return "";
        return c.label + ": expected " + hitText(want.x) + ", got " + hitText(got.x);
    }
    if (gotHit && std::fabs(got.x - want.x) > 1e-4 * std::max(1.0, want.x))
        return c.label + ": expected " + hitText(want.x) + ", got " + hitText(got.x);
    return "";
}

#ifndef RAYLAB_REFERENCES_AS_DATA
// The ray of a case whose a0.xyz is the origin and a1.xyz the direction
// (the references', which the page's core and a student build leave out).
reference::DRay rayOf(const FunctionCase& c) { return {xyz(c.in[0]), xyz(c.in[1])}; }
#endif

// The references are the reference tracer's own (reference_intersect.h,
// reference_shading.h): one double-precision version of each GLSL function.

// A small deterministic generator (the tables must not change between runs).
struct Lcg {
    std::uint64_t state;
    double next() {  // [0, 1)
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * (1.0 / 9007199254740992.0);
    }
    double in(double lo, double hi) { return lo + (hi - lo) * next(); }
    dvec3 direction() {
        double z = in(-1.0, 1.0), a = in(0.0, 6.283185307179586), r = std::sqrt(1.0 - z * z);
        return {r * std::cos(a), r * std::sin(a), z};
    }
};

FunctionCase rayCase(std::string label, dvec3 o, dvec3 d, dvec4 a2, dvec4 a3 = dvec4(0.0),
                     bool hitOrMiss = false) {
    FunctionCase c;
    c.label = std::move(label);
    c.in = {dvec4(o, 0.0), dvec4(glm::normalize(d), 0.0), a2, a3};
    c.hitOrMiss = hitOrMiss;
    return c;
}

}  // namespace

FunctionSpec sphereSpec() {
    FunctionSpec s;
    s.name = "intersectSphere";
    s.includes = {"ray.glsl", "intersect_sphere.glsl"};
    s.call = "vec4(intersectSphere(Ray(a0.xyz, a1.xyz), a2.xyz, a2.w), 0.0, 0.0, 1.0)";
    const dvec4 unit(0, 0, 0, 1);
    s.cases = {
        rayCase("head-on from outside", {0, 0, -5}, {0, 0, 1}, unit),
        rayCase("clear miss", {0, 2, -5}, {0, 0, 1}, unit),
        rayCase("from the centre (inside)", {0, 0, 0}, {0, 0, 1}, unit),
        rayCase("from inside, off centre", {0.3, -0.2, 0.1}, {1, 1, 0}, unit),
        rayCase("sphere behind the ray", {0, 0, 5}, {0, 0, 1}, unit),
        rayCase("starting on the surface, leaving", {0, 0, 1}, {0, 0, 1}, unit),
        rayCase("starting on the surface, entering", {0, 0, -1}, {0, 0, 1}, unit),
        rayCase("tangent ray", {1, 0, -5}, {0, 0, 1}, unit, {}, true),
        rayCase("nearly tangent, inside the rim", {0.999, 0, -5}, {0, 0, 1}, unit),
        rayCase("off-centre sphere", {1, 2, 3}, {1.5, -1.8, -2.2}, {2.5, 0.2, 0.8, 0.7}),
        rayCase("far small sphere", {0, 0, 0}, {0, 0, -1}, {0.01, 0, -200, 0.05}),
        rayCase("big sphere, eye inside", {5, 1, -2.4}, {0, 0, -1}, {0, -60, 0, 62}),
    };
    Lcg rng{1};
    for (int i = 0; i < 24; ++i) {
        // One draw per statement: the order in which a call's arguments are
        // evaluated is the compiler's choice (GCC's natively, clang's in the
        // page's core), and both must build the same cases. (This is the
        // order GCC gave the arguments, so the cases are those of before.)
        const double cz = rng.in(-3, 3), cy = rng.in(-3, 3), cx = rng.in(-3, 3);
        const dvec3 center(cx, cy, cz);
        const double oz = rng.in(-6, 6), oy = rng.in(-6, 6), ox = rng.in(-6, 6);
        const dvec3 o(ox, oy, oz);
        const double reach = rng.in(0.0, 1.5);
        const dvec3 aim = center + rng.direction() * reach - o;  // about half of them hit
        s.cases.push_back(rayCase("random ray " + std::to_string(i + 1), o, aim,
                                  dvec4(center, rng.in(0.3, 1.2))));
    }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::intersectSphere(rayOf(c), xyz(c.in[2]), c.in[2].w), 0, 0, 1);
    });
    s.compare = compareHit;
    return s;
}

FunctionSpec planeSpec() {
    FunctionSpec s;
    s.name = "intersectPlane";
    s.includes = {"ray.glsl", "intersect_plane.glsl"};
    s.call = "vec4(intersectPlane(Ray(a0.xyz, a1.xyz), a2.xyz, a2.w), 0.0, 0.0, 1.0)";
    const dvec4 floor(0, 1, 0, 0);
    s.cases = {
        rayCase("straight down", {0, 2, 0}, {0, -1, 0}, floor),
        rayCase("slanted", {1, 3, 2}, {0.3, -1, -0.4}, floor),
        rayCase("pointing away", {0, 2, 0}, {0, 1, 0}, floor),
        rayCase("parallel, above", {0, 1, 0}, {1, 0, 0}, floor),
        rayCase("parallel, in the plane", {0, 0, 0}, {0, 0, 1}, floor),
        rayCase("from below", {0, -2, 0}, {0.2, 1, 0}, floor),
        rayCase("starting on the plane", {0, 0, 0}, {0, -1, 0.3}, floor),
        rayCase("grazing", {0, 0.01, 0}, {1, -0.001, 0}, floor),
        rayCase("tilted plane, offset", {0, 0, 0}, {1, 1, 1},
                dvec4(glm::normalize(dvec3(1, 2, 3)), 4.0)),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::intersectPlane(rayOf(c), xyz(c.in[2]), c.in[2].w), 0, 0, 1);
    });
    s.compare = compareHit;
    return s;
}

FunctionSpec discSpec() {
    FunctionSpec s;
    s.name = "intersectDisc";
    s.includes = {"ray.glsl", "intersect_plane.glsl", "intersect_disc.glsl"};
    s.call = "vec4(intersectDisc(Ray(a0.xyz, a1.xyz), a2.xyz, a3.xyz, a2.w), 0.0, 0.0, 1.0)";
    const dvec4 disc(0, 1, 0, 2.0), up(0, 1, 0, 0);
    s.cases = {
        rayCase("through the centre", {0, 3, 0}, {0, -1, 0}, disc, up),
        rayCase("inside the rim", {1.9, 3, 0}, {0, -1, 0}, disc, up),
        rayCase("outside the rim", {2.1, 3, 0}, {0, -1, 0}, disc, up),
        rayCase("diagonal, outside (1.5, 1.5)", {1.5, 3, 1.5}, {0, -1, 0}, disc, up),
        rayCase("on the rim", {2.0, 3, 0}, {0, -1, 0}, disc, up, true),
        rayCase("parallel", {0, 1, -5}, {0, 0, 1}, disc, up),
        rayCase("from below", {0.5, -1, 0.5}, {0, 1, 0}, disc, up),
        // Radius 2: between sqrt(2) and 2 from the centre is inside; radius
        // 0.5: between 0.5 and sqrt(0.5) is outside (a distance squared
        // compared with the radius, not its square, gets these wrong).
        rayCase("radius 2, 1.6 from the centre", {1.6, 3, 0}, {0, -1, 0}, disc, up),
        rayCase("radius 2, 1.5 from the centre, diagonal", {1.06, 3, -1.06}, {0, -1, 0}, disc, up),
        rayCase("radius 0.5, 0.6 from the centre", {0.6, 3, 0}, {0, -1, 0}, dvec4(0, 1, 0, 0.5),
                up),
        rayCase("radius 0.5, 0.65 from the centre, diagonal", {-0.46, 3, 0.46}, {0, -1, 0},
                dvec4(0, 1, 0, 0.5), up),
        rayCase("tilted disc", {0, 0, 5}, {0.05, 0.02, -1}, dvec4(0, 0, 0, 0.5),
                dvec4(glm::normalize(dvec3(0.2, 0.1, 1)), 0)),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::intersectDisc(rayOf(c), xyz(c.in[2]), xyz(c.in[3]), c.in[2].w), 0,
                     0, 1);
    });
    s.compare = compareHit;
    return s;
}

// Triangle a, b, c packed into the spare w components: a0.w a1.w a2.w = a,
// a2.xyz = b, a3.xyz = c.
FunctionCase triangleCase(std::string label, dvec3 o, dvec3 d, dvec3 a, dvec3 b, dvec3 c,
                          bool hitOrMiss = false) {
    FunctionCase k;
    k.label = std::move(label);
    k.in = {dvec4(o, a.x), dvec4(glm::normalize(d), a.y), dvec4(b, a.z), dvec4(c, 0.0)};
    k.hitOrMiss = hitOrMiss;
    return k;
}

FunctionSpec triangleSpec() {
    FunctionSpec s;
    s.name = "intersectTriangle";
    s.includes = {"ray.glsl", "intersect_triangle.glsl"};
    s.call = "vec4(intersectTriangle(Ray(a0.xyz, a1.xyz), vec3(a0.w, a1.w, a2.w), a2.xyz, a3.xyz), "
             "0.0, 0.0, 1.0)";
    const dvec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);  // counter-clockwise seen from +z
    s.cases = {
        triangleCase("front face, inside", {0.5, 0.5, 3}, {0, 0, -1}, a, b, c),
        triangleCase("back face, inside (both sides count)", {0.5, 0.5, -3}, {0, 0, 1}, a, b, c),
        triangleCase("beyond the long edge (u + v > 1)", {1.2, 1.2, 3}, {0, 0, -1}, a, b, c),
        triangleCase("left of the edge a-c (u < 0)", {-0.1, 0.5, 3}, {0, 0, -1}, a, b, c),
        triangleCase("below the edge a-b (v < 0)", {0.5, -0.1, 3}, {0, 0, -1}, a, b, c),
        triangleCase("on the edge a-b", {1.0, 0.0, 3}, {0, 0, -1}, a, b, c, true),
        triangleCase("through a corner", {0.0, 0.0, 3}, {0, 0, -1}, a, b, c, true),
        triangleCase("parallel to the triangle", {0.5, 0.5, 1}, {1, 0, 0}, a, b, c),
        triangleCase("triangle behind the ray", {0.5, 0.5, 3}, {0, 0, 1}, a, b, c),
        triangleCase("slanted ray", {3, 2, 4}, {-2.6, -1.5, -4}, a, b, c),
        triangleCase("slanted triangle", {0, 0, 0}, {1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}),
        triangleCase("the parallelogram's other half", {1.5, 1.5, 3}, {0, 0, -1}, a, b, c),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& k) {
        dvec3 first(k.in[0].w, k.in[1].w, k.in[2].w);
        return dvec4(reference::intersectTriangle(rayOf(k), first, xyz(k.in[2]), xyz(k.in[3])), 0,
                     0, 1);
    });
    s.compare = compareHit;
    return s;
}

// torusQuartic(o, d, R, r): the coefficients (c3, c2, c1, c0) of the quartic
// in t whose roots are where the ray o + t d meets the torus (|d| = 1, the
// units intersectTorusUnit works in: 1 <= R < 2). A coefficient is right
// within 1e-4 of the largest one's size: float rounding, not a wrong term.
FunctionSpec torusQuarticSpec() {
    FunctionSpec s;
    s.name = "torusQuartic";
    s.includes = {"ray.glsl", "scene_objects.glsl", "intersect_torus.glsl"};
    s.call = "torusQuartic(a0.xyz, a1.xyz, a2.x, a2.y)";
    const struct {
        const char* label;
        dvec3 o, d;
        double R, r;
    } rows[] = {
        {"along the axis, through the hole", {0, 0, 3}, {0, 0, -1}, 1.0, 0.25},
        {"across the ring through the centre", {-3, 0, 0}, {1, 0, 0}, 1.0, 0.25},
        {"from inside the tube", {1.0, 0, 0.05}, {0, 1, 0}, 1.0, 0.25},
        {"a slanted ray", {-2, 1.5, 1}, glm::normalize(dvec3(0.8, -0.5, -0.3)), 1.5, 0.4},
        {"a fat torus (r = R / 2)",
         {0.3, -2.5, 0.7},
         glm::normalize(dvec3(0.1, 1, -0.2)),
         1.2,
         0.6},
        {"tangent to the outer equator", {-3, 1.3, 0}, {1, 0, 0}, 1.0, 0.3},
        {"R near 2", {2.5, 2.5, 0.5}, glm::normalize(dvec3(-1, -1, -0.1)), 1.9, 0.2},
    };
    for (const auto& r : rows) {
        FunctionCase c;
        c.label = r.label;
        c.in = {dvec4(r.o, 0), dvec4(r.d, 0), dvec4(r.R, r.r, 0, 0), dvec4(0.0)};
        s.cases.push_back(c);
    }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const dvec3 o(c.in[0]), d(c.in[1]);
        const double R = c.in[2].x, r = c.in[2].y;
        // f(o + t d) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p.x^2 + p.y^2), |d| = 1.
        const double m = glm::dot(o, o), n = glm::dot(o, d), k = m + R * R - r * r;
        const double R4 = 4.0 * R * R;
        return dvec4(4.0 * n, 4.0 * n * n + 2.0 * k - R4 * (d.x * d.x + d.y * d.y),
                     4.0 * n * k - 2.0 * R4 * (o.x * d.x + o.y * d.y),
                     k * k - R4 * (o.x * o.x + o.y * o.y));
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        const double size = std::max(
            {1.0, std::fabs(want.x), std::fabs(want.y), std::fabs(want.z), std::fabs(want.w)});
        return compareVector(c, got, want, 4, 1e-4 * size);
    };
    return s;
}

FunctionSpec torusNormalSpec() {
    FunctionSpec s;
    s.name = "torusNormalLocal";
    s.includes = {"ray.glsl", "scene_objects.glsl", "intersect_torus.glsl"};
    s.call = "vec4(torusNormalLocal(a0.xyz, a0.w, a1.x), 1.0)";
    const double R = 1.0, r = 0.25;
    for (int i = 0; i < 12; ++i) {
        double u = 0.5 * i, v = 1.3 * i + 0.2;
        dvec3 p((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                r * std::sin(v));
        FunctionCase c;
        c.label = "surface point " + std::to_string(i + 1);
        c.in = {dvec4(p, R), dvec4(r, 0, 0, 0), dvec4(0.0), dvec4(0.0)};
        s.cases.push_back(c);
    }
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        return dvec4(reference::torusNormalLocal(xyz(c.in[0]), c.in[0].w, c.in[1].x), 1.0);
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) {
        if (!allFinite(got)) return c.label + ": got NaN or Inf";
        if (std::fabs(glm::length(xyz(got)) - 1.0) > 1e-3)
            return c.label + ": the normal is not of unit length (" +
                   caseNumber(glm::length(xyz(got))) + ")";
        return compareVector(c, got, want, 3, 1e-3);
    };
    return s;
}

}  // namespace raylab
