// Shell slots (framework/src/raytrace/scene/shell_slots.h): a nearest-hit
// search tests, of each pair of a box-like shell's opposite faces, only the
// face the ray can meet the shell on first. Checked here on the CPU: the
// slots of pro's glass cube, no slots for shells that are not boxes, and
// rays from everywhere a GLSL ray starts whose first hit among the cube's 12
// triangles (an exact test in double) is also the first hit among the 6 the
// slots choose, the choice made in float as the GLSL makes it. The GPU side
// (the demo's views, the same bytes with and without the slots) is
// tests/e2e/bvh_images_test.cpp's ShellSlotsDrawWhatEveryTriangleDraws.
#include "convex_shell.h"
#include "paths.h"
#include "scene.h"
#include "shell_slots.h"
#include "triangle_groups.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

using namespace raylab;

namespace {

Scene slotsPro() { return loadScene(projectRoot() / "assets/scenes/pro.json"); }

constexpr double kTMin = 1e-4;  // ray.glsl's T_MIN

// The distance along unit D from O to triangle I, or -1 (Moeller and
// Trumbore in double).
double hitTriangle(const Scene& scene, int i, glm::dvec3 o, glm::dvec3 d) {
    const auto& v = scene.triangles[std::size_t(i)].vertices;
    const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0], p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-300) return -1.0;
    const glm::dvec3 s = o - v[0], q = glm::cross(s, e1);
    const double u = glm::dot(s, p) / det, w = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
    return u >= 0.0 && w >= 0.0 && u + w <= 1.0 && t > kTMin ? t : -1.0;
}

// How a slot chooses, as find_closest.glsl's SHELL_SLOT does: in float, against the planes
// as scene_baking.cpp bakes them.
enum class Rule { Slots, AlwaysTop, IgnoringTMin };
int chosen(const ShellSlot& s, glm::vec3 origin, glm::vec3 dir, Rule rule) {
    if (rule == Rule::AlwaysTop) return s.topTriangle;
    const glm::vec3 n(s.normal);
    const float top = float(s.top), bottom = float(s.bottom), tMin = float(kTMin);
    const float at = glm::dot(n, origin), along = glm::dot(n, dir);
    if (rule == Rule::IgnoringTMin)
        return (along < 0.0f ? at > top : at >= bottom) ? s.topTriangle : s.bottomTriangle;
    const bool isTop = along < 0.0f ? at - top > tMin * -along : bottom - at <= tMin * along;
    return isTop ? s.topTriangle : s.bottomTriangle;
}

struct SlotAudit {
    long rays = 0, hits = 0, lost = 0;
    long atTMin = 0;  // first hits at T_MIN, within rounding: either answer
};

// Rays from the eye, from the spheres' surfaces, from the cube's faces
// (moved off them to either side by up to 256 float steps, as
// ray_offset.glsl moves a ray that leaves them) and from anywhere around
// the cube; half aimed at a point in the cube, half anywhere.
SlotAudit auditSlots(const Scene& scene, const std::vector<TriangleGroup>& groups,
                     const std::vector<std::vector<ShellSlot>>& slots, Rule rule) {
    std::size_t g = 0;
    while (g < slots.size() && slots[g].empty()) ++g;
    const TriangleGroup& group = groups.at(g);
    const glm::dvec3 centre = 0.5 * (group.lo + group.hi);
    const double size = glm::length(group.hi - group.lo);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), zeroOne(0.0, 1.0);
    auto direction = [&] {
        glm::dvec3 v;
        do v = {unit(rng), unit(rng), unit(rng)};
        while (glm::length(v) > 1.0 || glm::length(v) < 1e-3);
        return glm::normalize(v);
    };
    SlotAudit a;
    for (int sample = 0; sample < 40000; ++sample) {
        glm::dvec3 p;
        switch (sample % 4) {
        case 0: p = scene.camera.position; break;
        case 1: {
            const Sphere& s = scene.spheres[std::size_t(sample / 4) % scene.spheres.size()];
            p = s.center + s.radius * direction();
            break;
        }
        case 2: {
            const int t = group.first + (sample / 4) % group.count;
            const auto& v = scene.triangles[std::size_t(t)].vertices;
            double u = zeroOne(rng), w = zeroOne(rng);
            if (u + w > 1.0) u = 1.0 - u, w = 1.0 - w;
            const glm::dvec3 on = v[0] + u * (v[1] - v[0]) + w * (v[2] - v[0]);
            const glm::dvec3 n = glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
            const double step = 256.0 * 1.2e-7 * (glm::length(on) + 1.0);
            p = on + (sample % 8 < 4 ? step : -step) * zeroOne(rng) * n;
            break;
        }
        default: p = centre + 1.5 * size * std::cbrt(zeroOne(rng)) * direction();
        }
        const glm::dvec3 aim = centre + 0.5 * size * unit(rng) * direction();
        const glm::dvec3 d =
            sample % 2 == 0 && glm::length(aim - p) > 1e-6 ? glm::normalize(aim - p) : direction();
        // The GLSL's ray is in float.
        const glm::vec3 origin(p), dir(d);
        const glm::dvec3 o(origin), dd(dir);
        ++a.rays;
        double all = -1.0;
        for (int i = group.first; i < group.first + group.count; ++i) {
            const double t = hitTriangle(scene, i, o, dd);
            if (t > 0.0 && (all < 0.0 || t < all)) all = t;
        }
        if (all < 0.0) continue;
        ++a.hits;
        double some = -1.0;
        for (const ShellSlot& s : slots[g]) {
            const double t = hitTriangle(scene, chosen(s, origin, dir, rule), o, dd);
            if (t > 0.0 && (some < 0.0 || t < some)) some = t;
        }
        // Two triangles of one face meet a ray on their shared edge at the
        // same point: the distance, not the triangle, must agree.
        if (some >= 0.0 && std::fabs(some - all) <= 1e-9 * (1.0 + all)) continue;
        // A first hit within rounding of T_MIN (a few float steps of the
        // cube's coordinates) is one the GPU's own float test may keep or
        // drop: the choice cannot be held to it (shell_slots.h, "Rounding").
        if (std::fabs(all - kTMin) < 1e-6) {
            ++a.atTMin;
            continue;
        }
        ++a.lost;
    }
    return a;
}

}  // namespace

TEST(ShellSlots, ProsCubeHasThreePairsOfFaces) {
    const Scene scene = slotsPro();
    const std::vector<TriangleGroup> groups = triangleGroups(scene);
    const std::vector<std::vector<ShellSlot>> slots = shellSlots(scene, groups);
    ASSERT_EQ(slots.size(), groups.size());
    EXPECT_TRUE(hasShellSlots(scene, groups));
    int shells = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (slots[g].empty()) continue;
        ++shells;
        EXPECT_EQ(groups[g].count, 12) << "the glass cube";
        ASSERT_EQ(slots[g].size(), 6u) << "half its triangles";
        std::set<int> seen;
        for (const ShellSlot& s : slots[g]) {
            EXPECT_GT(s.top - s.bottom, 1.7) << "the cube is 1.8 wide";
            for (int t : {s.topTriangle, s.bottomTriangle}) {
                seen.insert(t);
                for (const glm::dvec3& v : scene.triangles[std::size_t(t)].vertices) {
                    const double on = glm::dot(s.normal, v);
                    EXPECT_NEAR(on, t == s.topTriangle ? s.top : s.bottom, 1e-9);
                }
            }
        }
        EXPECT_EQ(seen.size(), 12u) << "every triangle in one slot";
    }
    EXPECT_EQ(shells, 1) << "the mirror is no shell";
}

TEST(ShellSlots, OnlyBoxLikeClosedShells) {
    Scene open = slotsPro();
    const auto groupsOf = [](const Scene& s) { return triangleGroups(s); };
    // An open box: one triangle gone.
    for (std::size_t i = 0; i < open.triangles.size(); ++i)
        if (open.triangles[i].material == open.triangles.back().material) {
            open.triangles.erase(open.triangles.begin() + std::ptrdiff_t(i));
            break;
        }
    EXPECT_FALSE(hasShellSlots(open, groupsOf(open)));
    // A closed convex shell whose faces have no opposite: a tetrahedron.
    Scene tetra = slotsPro();
    tetra.triangles.clear();
    const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);
    for (const auto& corners :
         {std::array<glm::dvec3, 3>{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}}) {
        Triangle t = slotsPro().triangles.front();
        t.vertices = corners;
        tetra.triangles.push_back(t);
    }
    ASSERT_EQ(convexShells(tetra).size(), 1u) << "a closed convex shell all the same";
    EXPECT_FALSE(hasShellSlots(tetra, groupsOf(tetra)));
    // No triangles at all.
    Scene none = slotsPro();
    none.triangles.clear();
    EXPECT_FALSE(hasShellSlots(none, groupsOf(none)));
}

TEST(ShellSlots, EveryFirstHitIsAmongTheSlots) {
    const Scene scene = slotsPro();
    const std::vector<TriangleGroup> groups = triangleGroups(scene);
    const SlotAudit a = auditSlots(scene, groups, shellSlots(scene, groups), Rule::Slots);
    std::printf("[ figure ] pro's cube: %ld rays, %ld meet it, %ld first hits lost by the slots, "
                "%ld within rounding of T_MIN (either answer)\n",
                a.rays, a.hits, a.lost, a.atTMin);
    EXPECT_GT(a.hits, 10000) << "too few rays meet the cube to say anything";
    EXPECT_EQ(a.lost, 0);
}

// The audit can fail: a rule that always takes the top face loses the
// first hits of the rays that meet a bottom face first; one that asks only
// which side of the plane the origin is on loses those of rays that start
// just outside a face and cross it before T_MIN (a ball resting on the
// cube, say), whose first hit is where they leave.
TEST(ShellSlots, AWrongChoiceIsCaught) {
    const Scene scene = slotsPro();
    const std::vector<TriangleGroup> groups = triangleGroups(scene);
    const auto slots = shellSlots(scene, groups);
    const SlotAudit top = auditSlots(scene, groups, slots, Rule::AlwaysTop);
    const SlotAudit side = auditSlots(scene, groups, slots, Rule::IgnoringTMin);
    std::printf("[ figure ] always the top face: %ld of %ld first hits lost; the origin's side "
                "only: %ld lost\n",
                top.lost, top.hits, side.lost);
    EXPECT_GT(top.lost, 1000);
    EXPECT_GT(side.lost, 100);
}
