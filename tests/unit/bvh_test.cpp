// The bounding volume hierarchy of stage 08 (framework/src/raytrace/scene/bvh.h): its
// structure, checked on the pro scene. The GPU traversal is checked by
// tests/e2e/bvh_images_test.cpp (images equal to the linear search).
#include "bvh.h"
#include "mesh_shapes.h"
#include "paths.h"
#include "scene.h"
#include "shader_constants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

using namespace raylab;

namespace {

Scene proScene() { return loadScene(projectRoot() / "assets/scenes/pro.json"); }

std::vector<int> sphereIndices(const Scene& s) {
    std::vector<int> ids;
    for (std::size_t i = 0; i < s.spheres.size(); ++i) ids.push_back(int(i));
    return ids;
}

// Visits every node from the root; FN(node, depth).
void walk(const Bvh& bvh, const std::function<void(const BvhNode&, int)>& fn) {
    std::function<void(int, int)> go = [&](int n, int depth) {
        const BvhNode& node = bvh.nodes.at(std::size_t(n));
        fn(node, depth);
        if (node.count == 0) {
            go(node.first, depth + 1);
            go(node.first + 1, depth + 1);
        }
    };
    go(0, 1);
}

}  // namespace

TEST(Bvh, EverySphereSitsInExactlyOneLeaf) {
    Scene scene = proScene();
    Bvh bvh = buildBvh(scene);
    std::vector<int> seen;
    walk(bvh, [&](const BvhNode& n, int) {
        for (int k = 0; k < n.count; ++k) seen.push_back(bvh.items.at(std::size_t(n.first + k)));
    });
    std::vector<int> expected = sphereIndices(scene);
    std::sort(seen.begin(), seen.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(seen, expected) << "leaves hold " << seen.size() << " items, the scene has "
                              << expected.size() << " spheres";
}

TEST(Bvh, EveryBoxHoldsItsChildrenAndObjects) {
    Scene scene = proScene();
    Bvh bvh = buildBvh(scene);
    int failures = 0;
    walk(bvh, [&](const BvhNode& n, int) {
        if (n.count == 0) {
            for (int c = 0; c < 2; ++c)
                if (!n.box.contains(bvh.nodes[std::size_t(n.first + c)].box)) ++failures;
        } else {
            for (int k = 0; k < n.count; ++k)
                if (!n.box.contains(sphereBounds(scene, bvh.items[std::size_t(n.first + k)])))
                    ++failures;
        }
    });
    EXPECT_EQ(failures, 0) << "boxes that do not hold what is under them";
}

// The tree is built in double (like the scene) and the GPU reads floats:
// each packed box is rounded outward, so it still holds its double box.
// Where float numbers are coarse (the scene 1e5 from the origin, not
// framed, with fractions) rounding to the nearest float would cut some
// boxes short, which shows the comparison can fail.
TEST(Bvh, PackedFloatBoxesHoldTheirDoubleBoxes) {
    Scene far = proScene();
    const glm::dvec3 shift(1e5 + 0.35, -1e5 - 0.123, 1e5 + 0.7);
    for (Sphere& s : far.spheres) s.center += shift;
    const Bvh bvh = buildBvh(far);
    const std::vector<float> packed = packedBvhNodes(bvh);
    int nearestWouldCut = 0;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const Aabb& box = bvh.nodes[i].box;
        for (int c = 0; c < 3; ++c) {
            const float lo = packed[8 * i + std::size_t(c)],
                        hi = packed[8 * i + 4 + std::size_t(c)];
            EXPECT_LE(double(lo), box.lo[c]) << "node " << i;
            EXPECT_GE(double(hi), box.hi[c]) << "node " << i;
            nearestWouldCut += double(float(box.lo[c])) > box.lo[c];
            nearestWouldCut += double(float(box.hi[c])) < box.hi[c];
        }
    }
    EXPECT_GT(nearestWouldCut, 0);
}

TEST(Bvh, TreeFitsTheGlslStackAndIsBalancedEnough) {
    Bvh bvh = buildBvh(proScene());
    int deepest = 0, leaves = 0;
    walk(bvh, [&](const BvhNode& n, int depth) {
        deepest = std::max(deepest, depth);
        if (n.count > 0) ++leaves;
    });
    EXPECT_EQ(deepest, bvh.depth);
    EXPECT_LE(bvh.depth, kBvhMaxDepth) << "the GLSL traversal stack holds " << kBvhMaxDepth;
    // 110 spheres in leaves of at most 2: a sensible tree is ~log2(55) + a few deep.
    EXPECT_LE(bvh.depth, 16) << "expected a shallow tree, got depth " << bvh.depth;
    EXPECT_EQ(int(bvh.nodes.size()), 2 * leaves - 1) << "every inner node has exactly two children";
}

TEST(Bvh, AMovingSphereStaysInItsBoxAtEveryTime) {
    Scene scene = proScene();
    int moving = 0;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        if (s.motion.amplitude == 0.0f) continue;
        ++moving;
        Aabb box = sphereBounds(scene, int(i));
        for (int k = 0; k <= 64; ++k) {
            float t = s.motion.periodSeconds * float(k) / 64.0f;
            const glm::dvec3 c = s.center + s.motion.offsetAt(t);
            Aabb at{c - glm::dvec3(s.radius), c + glm::dvec3(s.radius)};
            ASSERT_TRUE(box.contains(at)) << "sphere " << i << " leaves its box at t = " << t;
        }
    }
    EXPECT_GT(moving, 0) << "the pro scene should have moving spheres to check";
}

TEST(Bvh, ASceneWithoutSpheresHasNoTree) {
    Scene scene;
    scene.planes.push_back({});
    Bvh bvh = buildBvh(scene);
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.items.empty());
}

// Spheres and mesh triangles in one tree (stage 08 with meshes).
namespace {

Scene meshScene() { return loadScene(projectRoot() / "assets/scenes/mesh.json"); }

// Leaves whose kind is neither spheres nor mesh triangles.
int otherKindLeaves(const Bvh& bvh) {
    int n = 0;
    walk(bvh, [&](const BvhNode& node, int) {
        if (node.count > 0 && node.kind != shader::kMesh && node.kind != shader::kSphere) ++n;
    });
    return n;
}

}  // namespace

TEST(Bvh, EverySphereAndMeshTriangleSitsInExactlyOneLeafOfItsKind) {
    Scene scene = meshScene();
    // A triangle and a disc of the scene file's own: the default tree
    // leaves them out (find_closest.glsl tests them in a loop); the tree-all
    // one takes them, which shows the count below can fail.
    scene.triangles.push_back({{glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)}, 0});
    scene.discs.push_back({glm::dvec3(0, 2, 0), glm::vec3(0, 1, 0), 0.5, 0});
    EXPECT_GT(otherKindLeaves(buildBvh(scene, 2, BvhObjects::AllBounded)), 0);
    Bvh bvh = buildBvh(scene);
    std::vector<int> spheres, triangles;
    int failures = 0;
    walk(bvh, [&](const BvhNode& n, int) {
        for (int k = 0; k < n.count; ++k) {
            const int item = bvh.items.at(std::size_t(n.first + k));
            (n.kind == shader::kMesh ? triangles : spheres).push_back(item);
            const Aabb box = n.kind == shader::kMesh ? meshTriangleBounds(scene, item)
                                                     : sphereBounds(scene, item);
            if (!n.box.contains(box)) ++failures;
        }
    });
    std::sort(spheres.begin(), spheres.end());
    std::sort(triangles.begin(), triangles.end());
    std::vector<int> allTriangles(meshTriangleCount(scene));
    for (std::size_t i = 0; i < allTriangles.size(); ++i) allTriangles[i] = int(i);
    EXPECT_EQ(otherKindLeaves(bvh), 0);
    EXPECT_EQ(spheres, sphereIndices(scene));
    EXPECT_EQ(triangles, allTriangles);
    EXPECT_EQ(failures, 0) << "leaf boxes that do not hold their objects";
}

// The kinds' item counts add up: no item is counted under the wrong kind.
TEST(Bvh, LeavesHoldOneKindAndTheCountsAddUp) {
    Scene scene = meshScene();
    Bvh bvh = buildBvh(scene);
    std::size_t sphereItems = 0, triangleItems = 0;
    walk(bvh, [&](const BvhNode& n, int) {
        if (n.count == 0) return;
        (n.kind == shader::kMesh ? triangleItems : sphereItems) += std::size_t(n.count);
    });
    EXPECT_EQ(sphereItems, scene.spheres.size());
    EXPECT_EQ(triangleItems, meshTriangleCount(scene));
    EXPECT_EQ(bvh.items.size(), sphereItems + triangleItems);
}

// Half a million triangles: the tree must still fit the GLSL stack (the
// builder halves by count where the levels left run short).
TEST(Bvh, AHugeMeshFitsTheGlslStack) {
    Scene scene;
    scene.meshes.push_back(placeMesh("sphere", makeShape("sphere", 350), 1.0, glm::dvec3(0.0), 0));
    ASSERT_GT(meshTriangleCount(scene), 480000u);
    Bvh bvh = buildBvh(scene, 2);
    int deepest = 0;
    walk(bvh, [&](const BvhNode& n, int depth) {
        deepest = std::max(deepest, depth);
        EXPECT_LE(n.count, 2);
    });
    EXPECT_EQ(deepest, bvh.depth);
    EXPECT_LE(bvh.depth, kBvhMaxDepth);
    std::printf("[ figure ] %zu triangles: %zu nodes, depth %d\n", meshTriangleCount(scene),
                bvh.nodes.size(), bvh.depth);
}

// The depth guard itself: triangles spread evenly in log(x) from 1 to 2^56,
// each a quarter of its distance in size (areas stay within float range).
// An area split can only peel the few biggest off the rest (all the others
// fall into the first of its 12 bins), so the tree would be far deeper than
// the GLSL stack and buildBvh would throw. The builder halves by count
// instead where the levels left run short.
TEST(Bvh, ALopsidedMeshIsHalvedRatherThanTooDeep) {
    Mesh m;
    m.name = "spread";
    for (int i = 0; i < 2000; ++i) {
        const float x = std::exp2(56.0f * float(i) / 2000.0f), size = 0.25f * x;
        const auto base = std::uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(),
                           {glm::vec3(x, 0, 0), glm::vec3(x + size, 0, 0), glm::vec3(x, size, 0)});
        m.normals.insert(m.normals.end(), 3, glm::vec3(0, 0, 1));
        m.uvs.insert(m.uvs.end(), 3, glm::vec2(0));
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
    }
    Scene scene;
    scene.meshes.push_back(placeMesh("line", m, 1.0, glm::dvec3(0.0), 0));
    Bvh bvh;
    ASSERT_NO_THROW(bvh = buildBvh(scene, 1));
    EXPECT_LE(bvh.depth, kBvhMaxDepth);
}
