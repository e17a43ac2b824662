// Fresnel: the reflected share F against the exact Fresnel equations for
// unpolarised light, in double.
//
// 1. Glass (ior 1.5), light LEAVING it, the angle swept through the critical
//    angle (41.8 degrees). Measured through stage 04's trace() itself: the
//    eye inside a glass sphere whose only light is its ambient colour a, in a
//    black sky, at depth 2. Every pixel is then a (1 + F): the primary hit's
//    ambient, plus F times the ambient seen by the reflected ray; the
//    refracted ray (weight 1 - F) escapes into the black. So F = colour / a - 1
//    for the angle of incidence of that pixel's ray. The default (Schlick
//    with the cosine on the air side, F = 1 under total internal reflection)
//    must stay within Schlick's own error (0.036 at worst for ior 1.5);
//    Schlick with the incident cosine inside the glass
//    (RAYLAB_NAIVE_NUMERICS) is printed next to it - badly wrong just below
//    the critical angle.
// 2. Gold (n = 0.143, 0.375, 1.442; k = 3.983, 2.386, 1.603): the GLSL
//    fresnelConductor (Schlick with F0 from n and k, float32) against the
//    same formula in double (tight), and how far Schlick itself is from the
//    exact conductor Fresnel, per channel (a figure, with a loose bound).
#include "numerics_support.h"

#include "camera.h"
#include "scene.h"
#include "stage_renderer.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace raylab;
using namespace raylab::numerics;
using glm::dvec3;

namespace {

constexpr double kIor = 1.5;
constexpr double kAmbient = 0.5;

// Unpolarised reflectance at a boundary from index n1 into n2, cosI the
// incident cosine: the mean of the s and p Fresnel equations; 1 under total
// internal reflection.
double exactDielectric(double cosI, double n1, double n2) {
    const double sinT = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
    if (sinT >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sinT * sinT);
    const double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const double rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
    return 0.5 * (rs * rs + rp * rp);
}

// Unpolarised reflectance of a conductor n + ik seen from air at incident
// cosine cosI (the exact Fresnel equations with a complex index).
double exactConductor(double cosI, double n, double k) {
    const double c2 = cosI * cosI, s2 = 1.0 - c2;
    const double a2b2Minus = n * n - k * k - s2;
    const double a2b2 = std::sqrt(a2b2Minus * a2b2Minus + 4.0 * n * n * k * k);  // a^2 + b^2
    const double a = std::sqrt(std::max(0.0, 0.5 * (a2b2 + a2b2Minus)));
    const double rs = (a2b2 - 2.0 * a * cosI + c2) / (a2b2 + 2.0 * a * cosI + c2);
    const double rp = rs * (a2b2 * c2 - 2.0 * a * cosI * s2 + s2 * s2) /
                      (a2b2 * c2 + 2.0 * a * cosI * s2 + s2 * s2);
    return 0.5 * (rs + rp);
}

double schlick(double cosine, double f0) {
    return f0 + (1.0 - f0) * std::pow(std::clamp(1.0 - cosine, 0.0, 1.0), 5.0);
}

struct GlassFigures {
    double maxBelow = 0, maxAbove = 0, worstBelowDeg = 0;
    int below = 0, above = 0;
};

// A frame of stage 04 from inside the glass sphere; F per pixel against the
// exact value for that pixel's angle.
GlassFigures glassFromInside(bool naive) {
    test::ScratchDir dir;
    test::writeFile(dir / "inside-glass.json", R"({
  "comment": "tests/numerics/fresnel_test.cpp: the eye inside a glass sphere lit only by its ambient colour, in a black sky",
  "background": [0, 0, 0],
  "camera": { "position": [0.0, 0.0, 0.9], "yaw": 60.0, "pitch": 0.0, "fov_y": 90.0 },
  "materials": {
    "glass": { "type": "glass", "ior": 1.5, "ambient": [0.5, 0.5, 0.5], "diffuse": [0, 0, 0], "specular": [0, 0, 0], "shininess": 1 }
  },
  "lights": [],
  "spheres": [ { "center": [0.0, 0.0, 0.0], "radius": 1.0, "material": "glass" } ]
})");
    Scene scene = loadScene(dir / "inside-glass.json");
    ensureGlContext();
    StageInfo stage = findStage("04-recursion");
    if (naive) stage.extraDefines.push_back("RAYLAB_NAIVE_NUMERICS");
    constexpr int w = 256, h = 64;
    const Camera camera(scene.camera, scene.fovYDeg);
    StageRenderer renderer(stage, solutionSources(stage), scene, w, h, PixelFormat::Rgba32F);
    RenderSettings settings;
    settings.maxDepth = 2;
    renderer.render(camera, 0.0f, settings);
    const std::vector<float> rgba = renderer.target().readFloats();

    GlassFigures f;
    const dvec3 eye(scene.camera.position);
    const double sinCritical = 1.0 / kIor;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const dvec3 d = glm::normalize(dvec3(camera.rayDirection(x, y, w, h)));
            const double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1.0;
            const dvec3 p = eye + (-b + std::sqrt(b * b - c)) * d;  // leaving the unit sphere
            const double cosI = glm::dot(d, glm::normalize(p));
            const double sinI = std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
            if (std::fabs(sinI / sinCritical - 1.0) < 1e-5)
                continue;  // on the critical angle: float cannot tell
            const double want = exactDielectric(cosI, kIor, 1.0);
            const double got =
                double(rgba[(std::size_t(y) * w + std::size_t(x)) * 4]) / kAmbient - 1.0;
            const double error = std::isfinite(got) ? std::fabs(got - want) : 1e9;
            if (sinI < sinCritical) {
                ++f.below;
                if (error > f.maxBelow) {
                    f.maxBelow = error;
                    f.worstBelowDeg = std::asin(sinI) * 180.0 / M_PI;
                }
            } else {
                ++f.above;
                f.maxAbove = std::max(f.maxAbove, error);
            }
        }
    return f;
}

void print(const char* method, const GlassFigures& f) {
    std::printf("[ figure   ] glass, leaving, %-27s max |F - exact| below the critical angle %.4f "
                "(worst at %.2f deg, %d pixels), above %.2e (%d pixels)\n",
                method, f.maxBelow, f.worstBelowDeg, f.below, f.maxAbove, f.above);
}

}  // namespace

TEST(FresnelNumerics, LeavingGlassTheAirSideCosineIsRightNearTheCriticalAngleAndTheInsideOneIsNot) {
    const GlassFigures robust = glassFromInside(false);
    const GlassFigures naive = glassFromInside(true);
    print("default (air-side cosine):", robust);
    print("incident cosine inside:", naive);

    // For the record: Schlick with the incident cosine where refract() reports
    // total internal reflection (if F = 1 were not taken there).
    FunctionSpec spec;
    spec.name = "fresnelDielectric";
    spec.includes = {"ray.glsl", "fresnel.glsl"};
    spec.call = "vec4(fresnelDielectric(a0.x, a0.y), 0.0, 0.0, 1.0)";
    std::vector<double> cosines;
    for (double deg = 42.0; deg < 90.0; deg += 0.25) {
        cosines.push_back(std::cos(deg * M_PI / 180.0));
        FunctionCase c;
        c.in[0] = glm::dvec4(f32(cosines.back()), kIor, 0, 0);
        spec.cases.push_back(c);
    }
    const std::vector<glm::vec4> got = runSolution(spec, "04-recursion");
    double worst = 0;
    for (std::size_t i = 0; i < got.size(); ++i)
        worst = std::max(worst, std::fabs(double(got[i].x) - 1.0));
    std::printf("[ figure   ] glass, leaving, Schlick with the incident cosine under total "
                "internal reflection would be off by up to %.4f\n",
                worst);

    EXPECT_GT(robust.below, 1000) << "the frame must sweep the angles below the critical one";
    EXPECT_GT(robust.above, 1000) << "and above it";
    EXPECT_LE(robust.maxBelow, 0.04) << "Schlick's own error for ior 1.5 is 0.036";
    EXPECT_LE(robust.maxAbove, 1e-6) << "total internal reflection: F = 1";
    // The difference the default makes.
    EXPECT_GT(naive.maxBelow, 0.5);
}

TEST(FresnelNumerics,
     GoldConductorSchlickInFloatMatchesDoubleAndItsDistanceFromTheExactFresnelIsPrinted) {
    const dvec3 n(0.143, 0.375, 1.442), k(3.983, 2.386, 1.603);
    FunctionSpec spec;
    spec.name = "fresnelConductor";
    spec.includes = {"ray.glsl", "fresnel.glsl"};
    spec.call = "vec4(fresnelConductor(a0.x, a1.xyz, a2.xyz), 1.0)";
    constexpr int kSteps = 2000;
    std::vector<double> cosines;
    for (int i = 0; i <= kSteps; ++i) {
        cosines.push_back(f32(double(i) / kSteps));
        FunctionCase c;
        c.in = {glm::dvec4(cosines.back(), 0, 0, 0), glm::dvec4(dvec3(glm::vec3(n)), 0),
                glm::dvec4(dvec3(glm::vec3(k)), 0), glm::dvec4(0.0)};
        spec.cases.push_back(c);
    }
    const std::vector<glm::vec4> got = runSolution(spec, "04-recursion");
    const dvec3 nf = dvec3(glm::vec3(n)), kf = dvec3(glm::vec3(k));  // the float inputs the GPU saw
    double floatError = 0;
    dvec3 schlickError(0.0), worstDeg(0.0);
    for (std::size_t i = 0; i < got.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const double f0 = ((nf[ch] - 1) * (nf[ch] - 1) + kf[ch] * kf[ch]) /
                              ((nf[ch] + 1) * (nf[ch] + 1) + kf[ch] * kf[ch]);
            const double sameFormula = schlick(cosines[i], f0);
            floatError = std::max(floatError, std::isfinite(got[i][ch])
                                                  ? std::fabs(double(got[i][ch]) - sameFormula)
                                                  : 1e9);
            const double deviation =
                std::fabs(sameFormula - exactConductor(cosines[i], nf[ch], kf[ch]));
            if (deviation > schlickError[ch]) {
                schlickError[ch] = deviation;
                worstDeg[ch] = std::acos(cosines[i]) * 180.0 / M_PI;
            }
        }
    std::printf("[ figure   ] gold, fresnelConductor in float vs the same formula in double: max "
                "|difference| %.2e over %d angles\n",
                floatError, int(got.size()));
    std::printf("[ figure   ] gold, Schlick vs the exact conductor Fresnel: max |difference| red "
                "%.4f (at %.1f deg), green %.4f (at %.1f deg), blue %.4f (at %.1f deg)\n",
                schlickError.r, worstDeg.r, schlickError.g, worstDeg.g, schlickError.b, worstDeg.b);
    EXPECT_LE(floatError, 1e-5);
    // Schlick is an approximation: a sanity bound, not a target.
    for (int ch = 0; ch < 3; ++ch) EXPECT_LE(schlickError[ch], 0.25);
}
