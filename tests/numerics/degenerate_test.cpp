// Degenerate and non-finite cases:
//  - the eye inside a glass sphere: a full stage-08 frame (lite scene) has
//    no NaN or Inf and a sensible picture;
//  - a ray lying in a plane (intersectPlane): no hit, no NaN;
//  - degenerate triangles (three corners on a line, a corner repeated):
//    no hit, no NaN, with either triangle method;
//  - the NaN guard of stage 08's main.frag: a frame whose colours would be
//    NaN (every material's ambient colour NaN, which the scene loader
//    refuses, set in memory to stand for any 0/0 in the tracer) reaches the
//    framebuffer without one NaN, the pixels shown magenta; stage 07's
//    tracer, which has no guard, lets the NaN through.
#include "numerics_support.h"

#include "camera.h"
#include "paths.h"
#include "scene.h"
#include "stage_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

using namespace raylab;
using namespace raylab::numerics;
using glm::dvec3;

namespace {

dvec3 rounded(dvec3 v) { return dvec3(f32(v.x), f32(v.y), f32(v.z)); }

struct FrameFigures {
    long pixels = 0, nonFinite = 0, guarded = 0, black = 0;
    double mean = 0, spread = 0, brightest = 0;
};

// Stage STAGEID's solution, 160x120 float frame of SCENE from POSE.
FrameFigures renderFrame(const std::string& stageId, const Scene& scene, const CameraPose& pose,
                         const std::vector<std::string>& defines = {}) {
    ensureGlContext();
    StageInfo stage = findStage(stageId);
    stage.extraDefines.insert(stage.extraDefines.end(), defines.begin(), defines.end());
    constexpr int w = 160, h = 120;
    StageRenderer renderer(stage, solutionSources(stage), scene, w, h, PixelFormat::Rgba32F);
    renderer.render(Camera(pose, scene.fovYDeg), 0.0f, RenderSettings{});
    const std::vector<float> rgba = renderer.target().readFloats();
    FrameFigures f;
    double sum = 0, sumSq = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        const glm::dvec3 c(rgba[i], rgba[i + 1], rgba[i + 2]);
        ++f.pixels;
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) {
            ++f.nonFinite;
            continue;
        }
        if (c == glm::dvec3(1.0, 0.0, 1.0))
            ++f.guarded;  // NON_FINITE_COLOR: no traced colour is exactly that
        const double luminance = (c.r + c.g + c.b) / 3.0;
        f.black += luminance < 1e-3;
        f.brightest = std::max(f.brightest, std::max(c.r, std::max(c.g, c.b)));
        sum += luminance;
        sumSq += luminance * luminance;
    }
    const double n = double(std::max(f.pixels - f.nonFinite, 1L));
    f.mean = sum / n;
    f.spread = std::sqrt(std::max(0.0, sumSq / n - f.mean * f.mean));
    return f;
}

void print(const char* what, const FrameFigures& f) {
    std::printf("[ figure   ] %-44s %ld pixels: NaN/Inf %ld, guarded (magenta) %ld, black %ld; "
                "luminance mean %.3f, spread %.3f, brightest channel %.3f\n",
                what, f.pixels, f.nonFinite, f.guarded, f.black, f.mean, f.spread, f.brightest);
}

Scene lite() { return loadScene(projectRoot() / "assets" / "scenes" / "lite.json"); }

}  // namespace

TEST(DegenerateNumerics, EyeInsideTheGlassSphereRendersAFullFrameWithoutNaN) {
    const Scene scene = lite();
    int glass = -1;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (scene.materials[std::size_t(scene.spheres[i].material)].type == Material::Type::Glass)
            glass = int(i);
    ASSERT_GE(glass, 0) << "lite.json has a glass sphere";
    const Sphere& s = scene.spheres[std::size_t(glass)];
    const CameraPose inside{
        s.center + s.motion.offsetAt(0.0f) + glm::dvec3(0.1, 0.05, 0.2) * s.radius, -20.0f, -5.0f};
    ASSERT_LT(glm::length(inside.position - s.center), s.radius);
    const FrameFigures robust = renderFrame("08-full", scene, inside);
    const FrameFigures naive = renderFrame("08-full", scene, inside, {"RAYLAB_NAIVE_NUMERICS"});
    print("eye inside the glass sphere, default", robust);
    print("eye inside the glass sphere, naive numerics", naive);
    EXPECT_EQ(robust.nonFinite, 0);
    EXPECT_EQ(robust.guarded, 0) << "no NaN may have been caught by the guard either";
    // A sensible picture: mostly lit (the scene through the glass, total
    // internal reflection at the rim), not one flat colour, nothing absurd.
    EXPECT_LT(robust.black, robust.pixels / 10);
    EXPECT_GT(robust.mean, 0.05);
    EXPECT_LT(robust.mean, 1.5);
    EXPECT_GT(robust.spread, 0.02);
    EXPECT_LT(robust.brightest, 10.0);
}

TEST(DegenerateNumerics, RayLyingInAPlaneMissesIt) {
    FunctionSpec spec;
    spec.name = "intersectPlane";
    spec.includes = {"ray.glsl", "intersect_plane.glsl"};
    spec.call = "vec4(intersectPlane(Ray(a0.xyz, a1.xyz), a2.xyz, a2.w), 0.0, 0.0, 1.0)";
    const dvec3 normals[] = {{0, 1, 0},
                             {1, 0, 0},
                             {0, 0, -1},
                             glm::normalize(dvec3(0.2, 1.0, 0.3)),
                             glm::normalize(dvec3(1, 1, 1)),
                             glm::normalize(dvec3(-0.7, 0.1, 0.4))};
    int cases = 0;
    for (const dvec3& exactNormal : normals) {
        const dvec3 normal = rounded(exactNormal);
        for (double offset : {0.0, 1.0, -2.5, 40.0}) {
            // Points of the plane and directions within it, as float numbers:
            // the origin lies in the plane as exactly as float allows, the
            // direction is parallel to it as exactly as float allows.
            const dvec3 u = glm::normalize(glm::cross(
                exactNormal, std::fabs(exactNormal.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
            const dvec3 v = glm::cross(exactNormal, u);
            for (int i = 0; i < 12; ++i) {
                const double a = 0.5236 * i;
                const dvec3 origin = rounded(exactNormal * offset + 3.0 * std::cos(1.3 * a) * u +
                                             2.0 * std::sin(0.7 * a) * v);
                const dvec3 dir = rounded(glm::normalize(std::cos(a) * u + std::sin(a) * v));
                FunctionCase c;
                c.in = {glm::dvec4(origin, 0), glm::dvec4(dir, 0), glm::dvec4(normal, offset),
                        glm::dvec4(0.0)};
                spec.cases.push_back(c);
                ++cases;
            }
        }
    }
    const std::vector<glm::vec4> got = runSolution(spec, "08-full");
    int hits = 0, nonFinite = 0;
    for (const glm::vec4& r : got) {
        nonFinite += !std::isfinite(r.x);
        hits += r.x > 0.0f && std::isfinite(r.x);
    }
    std::printf("[ figure   ] rays lying in a plane: %d rays, %d hits, %d NaN/Inf\n", cases, hits,
                nonFinite);
    EXPECT_EQ(hits, 0);
    EXPECT_EQ(nonFinite, 0);
}

TEST(DegenerateNumerics, DegenerateTrianglesAreNeverHitByEitherMethod) {
    // Corners on a line, exactly (coordinates with few bits: the middle one
    // is exactly between the others in float), and corners repeated.
    const dvec3 a(0.5, -1.25, 3.0), e(0.25, 0.75, -0.5);
    const std::vector<std::array<dvec3, 3>> triangles = {
        {a, a + e, a + 2.0 * e},                           // on a line, in order
        {a + 2.0 * e, a, a + e},                           // on a line, the middle corner last
        {a, a + 4.0 * e, a + 1.5 * e},                     // on a line, uneven
        {a, a, a + e},                                     // two corners the same
        {a + e, a, a},                                     // two corners the same, the other order
        {a, a, a},                                         // a point
        {dvec3(1, 0, 0), dvec3(3, 0, 0), dvec3(2, 0, 0)},  // on a coordinate axis
    };
    FunctionSpec spec;
    spec.name = "intersectTriangle";
    spec.includes = {"ray.glsl", "intersect_triangle.glsl"};
    spec.call = "vec4(intersectTriangle(Ray(a0.xyz, a1.xyz), vec3(a0.w, a1.w, a2.w), a2.xyz, "
                "a3.xyz), 0.0, 0.0, 1.0)";
    const dvec3 eyes[] = {{0, 0, 10}, {5, 5, 5}, {-3, 2, -4}, {0.5, 30, 3}};
    for (const auto& t : triangles)
        for (const dvec3& eye : eyes)
            for (int k = 0; k <= 8; ++k) {
                // Rays at points along the degenerate triangle's extent and at its corners.
                const dvec3 target = k == 8 ? t[2]
                                            : t[0] + (k / 7.0) * (t[1] - t[0]) +
                                                  (k % 3 == 0 ? 0.25 : 0.0) * (t[2] - t[0]);
                if (glm::length(target - eye) < 1e-9) continue;
                const dvec3 dir = rounded(glm::normalize(target - eye));
                FunctionCase c;
                c.in = {glm::dvec4(eye, t[0].x), glm::dvec4(dir, t[0].y), glm::dvec4(t[1], t[0].z),
                        glm::dvec4(t[2], 0.0)};
                spec.cases.push_back(c);
            }
    for (bool naive : {false, true}) {
        const std::vector<glm::vec4> got = runSolution(
            spec, "08-full",
            naive ? std::vector<std::string>{"RAYLAB_NAIVE_NUMERICS"} : std::vector<std::string>{});
        int hits = 0, nonFinite = 0;
        for (const glm::vec4& r : got) {
            nonFinite += !std::isfinite(r.x);
            hits += r.x > 0.0f && std::isfinite(r.x);
        }
        std::printf("[ figure   ] degenerate triangles, %-16s %zu rays, %d hits, %d NaN/Inf\n",
                    naive ? "Moller-Trumbore:" : "watertight:", got.size(), hits, nonFinite);
        EXPECT_EQ(hits, 0) << (naive ? "Moller-Trumbore" : "watertight");
        EXPECT_EQ(nonFinite, 0) << (naive ? "Moller-Trumbore" : "watertight");
    }
}

TEST(DegenerateNumerics, NaNGuardKeepsEveryNaNOutOfTheStage08Framebuffer) {
    Scene scene = lite();
    for (Material& m : scene.materials)
        m.ambient = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    const FrameFigures unguarded = renderFrame("07-normalmaps", scene, scene.camera);
    const FrameFigures guarded = renderFrame("08-full", scene, scene.camera);
    print("NaN materials, stage 07 (no guard)", unguarded);
    print("NaN materials, stage 08 (guard)", guarded);
    EXPECT_GT(unguarded.nonFinite, guarded.pixels / 10) << "the scene must provoke NaN colours";
    EXPECT_EQ(guarded.nonFinite, 0);
    EXPECT_GT(guarded.guarded, guarded.pixels / 10) << "the NaN pixels are shown magenta";
    // The clean scene has none of either.
    const FrameFigures clean = renderFrame("08-full", lite(), lite().camera);
    print("lite scene, stage 08", clean);
    EXPECT_EQ(clean.nonFinite, 0);
    EXPECT_EQ(clean.guarded, 0);
}
