// A small sphere far away: intersectSphere (stage 01's solution, float32)
// against a double-precision reference, for a sphere of radius 1 seen from
// 100, 1000 and 10000 radii, over a 128x128 grid of rays that covers the
// sphere and some sky around it.
//
// The textbook discriminant h = b*b - c (RAYLAB_NAIVE_NUMERICS) subtracts
// two numbers of size distance^2 to get one of size radius^2: at 10^4 radii
// float keeps about 7 digits, the difference needs 8, and h is noise - rays
// hit or miss at random. The default computes h = r^2 - |oc - b d|^2 (the
// closest approach of the ray's line, no large terms) and the near root as
// c / q: it must never disagree with the reference on hit or miss and stay
// within 8 float ulps of t at the 99th percentile (3.5 measured; near the
// rim t is sensitive as the square root of h's rounding). Both methods' figures are printed.
#include "numerics_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace raylab;
using namespace raylab::numerics;
using glm::dvec3;

namespace {

constexpr int kSphereGrid = 128;
constexpr double kRadius = 1.0;

struct Reference {
    double t = -1.0;         // -1: miss
    bool ambiguous = false;  // grazes the rim: float cannot decide, both answers right
};

// Exact in double: the ray's closest approach to the centre decides hit or
// miss; t is the entry point. D need not be of unit length (it is a float
// direction), so everything is divided by |D|^2 where it matters.
Reference reference(dvec3 o, dvec3 d, dvec3 center, double radius, double band) {
    Reference ref;
    const dvec3 oc = o - center;
    const double dd = glm::dot(d, d);
    const double along = -glm::dot(oc, d) / dd;  // parameter of the closest point
    const dvec3 closest = oc + along * d;
    const double miss = glm::length(closest) - radius;  // > 0: passes outside
    ref.ambiguous = std::fabs(miss) < band;
    if (miss <= 0.0) {
        const double halfChord =
            std::sqrt(std::max(radius * radius - glm::dot(closest, closest), 0.0) / dd);
        ref.t = along - halfChord;
    }
    return ref;
}

struct SphereFigures {
    double wrongShare = 0, p50 = 0, p99 = 0, maxUlps = 0;
    int rays = 0, hits = 0, wrong = 0;
};

SphereFigures measureSphere(double ratio, bool naive) {
    FunctionSpec spec;
    spec.name = "intersectSphere";
    spec.includes = {"ray.glsl", "intersect_sphere.glsl"};
    spec.call = "vec4(intersectSphere(Ray(a0.xyz, a1.xyz), a2.xyz, a2.w), 0.0, 0.0, 1.0)";
    // The eye near the world origin (as in every scene), the sphere RATIO
    // radii away in a tilted direction; all inputs are float numbers.
    const dvec3 eye(0.25, 1.5, 0.75);
    const dvec3 toSphere = glm::normalize(dvec3(0.35, -0.2, -0.9));
    const dvec3 c = eye + ratio * kRadius * toSphere;
    const dvec3 center(f32(c.x), f32(c.y), f32(c.z));
    const dvec3 o(f32(eye.x), f32(eye.y), f32(eye.z));
    const dvec3 forward = glm::normalize(center - o);
    const dvec3 right = glm::normalize(glm::cross(forward, dvec3(0, 1, 0)));
    const dvec3 up = glm::cross(right, forward);
    // Hit or miss is undecidable for float within a few float steps of the
    // eye-to-sphere distance at the rim: the direction itself is only known
    // to 6e-8, which moves the ray by 6e-8 x distance there.
    const double band = 1e-5 * kRadius + 8.0 * floatUlp(ratio * kRadius);
    std::vector<Reference> refs;
    for (int y = 0; y < kSphereGrid; ++y)
        for (int x = 0; x < kSphereGrid; ++x) {
            const dvec3 target =
                center + kRadius * (right * (-1.4 + 2.8 * (x + 0.5) / kSphereGrid) +
                                    up * (-1.4 + 2.8 * (y + 0.5) / kSphereGrid));
            dvec3 dir = glm::normalize(target - o);
            dir = dvec3(f32(dir.x), f32(dir.y), f32(dir.z));
            FunctionCase k;
            k.in = {glm::dvec4(o, 0), glm::dvec4(dir, 0), glm::dvec4(center, kRadius),
                    glm::dvec4(0.0)};
            spec.cases.push_back(k);
            refs.push_back(reference(o, dir, center, kRadius, band));
        }
    std::vector<std::string> defines;
    if (naive) defines.push_back("RAYLAB_NAIVE_NUMERICS");
    const std::vector<glm::vec4> got = runSolution(spec, "01-raycast", defines);

    SphereFigures f;
    int decided = 0;
    std::vector<double> ulps;
    for (std::size_t i = 0; i < refs.size(); ++i) {
        const bool gotHit = got[i].x > 0.0f && std::isfinite(got[i].x);
        const bool refHit = refs[i].t >= 0.0;
        f.hits += refHit;
        if (!refs[i].ambiguous) {
            ++decided;
            f.wrong += gotHit != refHit;
            if (gotHit != refHit && !naive && f.wrong <= 5)
                std::printf("[ wrong    ] ray %zu: reference %s, solution %s t = %.9g\n", i,
                            refHit ? "hit" : "miss", gotHit ? "hit at" : "miss,", double(got[i].x));
        }
        if (gotHit && refHit)
            ulps.push_back(std::fabs(double(got[i].x) - refs[i].t) / floatUlp(refs[i].t));
    }
    f.rays = int(refs.size());
    f.wrongShare = double(f.wrong) / double(std::max(decided, 1));
    f.p50 = percentile(ulps, 50);
    f.p99 = percentile(ulps, 99);
    f.maxUlps = percentile(ulps, 100);
    return f;
}

void printSphere(const char* method, double ratio, const SphereFigures& f) {
    std::printf("[ figure   ] sphere at %6.0f radii, %-9s wrong hit/miss %7.3f%% (%5d rays), |t "
                "error| p50 %10.1f ulp, p99 %10.1f ulp, max %10.1f ulp (%d rays, %d hits)\n",
                ratio, method, f.wrongShare * 100.0, f.wrong, f.p50, f.p99, f.maxUlps, f.rays,
                f.hits);
}

}  // namespace

TEST(SphereNumerics, StableDiscriminantIsRightFarAwayAndTheTextbookOneIsNot) {
    double naiveWrongFar = 0;
    for (double ratio : {1e2, 1e3, 1e4}) {
        SCOPED_TRACE(ratio);
        const SphereFigures robust = measureSphere(ratio, false);
        const SphereFigures naive = measureSphere(ratio, true);
        printSphere("default", ratio, robust);
        printSphere("textbook", ratio, naive);
        EXPECT_GT(robust.hits, kSphereGrid * kSphereGrid / 4) << "the grid must cover the sphere";
        EXPECT_EQ(robust.wrong, 0);
        EXPECT_LE(robust.p99, 8.0);
        if (ratio >= 1e4) naiveWrongFar = naive.wrongShare;
    }
    // The difference the default makes: at 10^4 radii the textbook form
    // decides hit or miss by rounding noise.
    EXPECT_GT(naiveWrongFar, 0.05);
}
