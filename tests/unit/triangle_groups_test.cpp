// Stage 08's groups of scene triangles (framework/src/raytrace/scene/triangle_groups.h):
// runs of one material, at most kTriangleGroupMax long, with the exact box
// of their corners. The GPU side is checked by the stage 08 views
// (tests/e2e/bvh_images_test.cpp, StageChecks) against the reference tracer.
#include "paths.h"
#include "scene.h"
#include "triangle_groups.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {

Triangle triangle(glm::dvec3 offset, int material) {
    return {{offset, offset + glm::dvec3(1, 0, 0), offset + glm::dvec3(0, 1, 0)}, material};
}

}  // namespace

// pro: the mirror (a rectangle: 2 triangles) and the glass cube (12).
TEST(TriangleGroups, ProHasTheMirrorAndTheCube) {
    Scene scene = loadScene(projectRoot() / "assets/scenes/pro.json");
    std::vector<TriangleGroup> groups = triangleGroups(scene);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].first, 0);
    EXPECT_EQ(groups[0].count, 2);
    EXPECT_EQ(groups[1].first, 2);
    EXPECT_EQ(groups[1].count, 12);
}

// Every triangle is in exactly one group, in order, and every corner lies
// in its group's box, touching it on each side (the box is exact).
TEST(TriangleGroups, GroupsCoverTheTrianglesInOrderWithExactBoxes) {
    Scene scene;
    for (int i = 0; i < 30; ++i)
        scene.triangles.push_back(
            triangle(glm::dvec3(i, i % 7, -(i % 3)), i < 5 ? 0 : (i < 7 ? 1 : 2)));
    std::vector<TriangleGroup> groups = triangleGroups(scene);
    int next = 0;
    for (const TriangleGroup& g : groups) {
        EXPECT_EQ(g.first, next);
        EXPECT_GE(g.count, 1);
        EXPECT_LE(g.count, kTriangleGroupMax);
        glm::dvec3 lo(1e30), hi(-1e30);
        for (int i = g.first; i < g.first + g.count; ++i) {
            EXPECT_EQ(scene.triangles[std::size_t(i)].material,
                      scene.triangles[std::size_t(g.first)].material);
            for (const glm::dvec3& p : scene.triangles[std::size_t(i)].vertices) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        }
        EXPECT_EQ(g.lo, lo);
        EXPECT_EQ(g.hi, hi);
        next += g.count;
    }
    EXPECT_EQ(next, 30);
    // Runs: 5 of material 0, 2 of material 1, 23 of material 2 in 12 + 11.
    ASSERT_EQ(groups.size(), 4u);
    EXPECT_EQ(groups[2].count, 12);
    EXPECT_EQ(groups[3].count, 11);
}

TEST(TriangleGroups, NoTrianglesNoGroups) { EXPECT_TRUE(triangleGroups(Scene{}).empty()); }
