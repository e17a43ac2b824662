// The BVH's one-texel nodes for the eye-cells walk
// (framework/src/raytrace/scene/bvh_boxes.h): decoded as the GLSL decodes
// them (origin + q * step, the multiply and add rounded apart or fused),
// every box holds its node's box, and first and code come back whole.
// The pictures are checked by VariantViews.EyeCellsDrawWhatTheWalkDraws.
#include "bvh.h"
#include "bvh_boxes.h"
#include "paths.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;

namespace {

Scene demoScene(const char* name) {
    return loadScene(projectRoot() / "assets" / "scenes" / (std::string(name) + ".json"));
}

// Both ways the GLSL may round origin + q * step (bvh_boxes.h's decoding).
void decodedBoth(float origin, float step, int q, double& low, double& high) {
    float apart, fused;
    bvh_boxes_detail::decoded(origin, step, q, apart, fused);
    low = std::min(double(apart), double(fused));
    high = std::max(double(apart), double(fused));
}

struct Audit {
    int nodes = 0;
    int notHeld = 0;          // a box that does not hold its node's box
    int wrongCode = 0;        // first or code not as the node's
    int tighterWouldCut = 0;  // one step tighter would cut the node's box
};

Audit audit(const Bvh& bvh) {
    Audit a;
    std::vector<float> texels;
    appendBvhBoxTexels(bvh, texels);
    const BvhBoxGrid g = bvhBoxGrid(bvh);
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& n = bvh.nodes[i];
        const float* t = &texels[8 * i];
        ++a.nodes;
        for (int axis = 0; axis < 3; ++axis) {
            const int packed = int(t[axis]);
            const int qlo = packed & kBvhBoxTop, qhi = packed >> kBvhBoxBits;
            double lowLo, highLo, lowHi, highHi;
            decodedBoth(g.origin[axis], g.step[axis], qlo, lowLo, highLo);
            decodedBoth(g.origin[axis], g.step[axis], qhi, lowHi, highHi);
            if (highLo > n.box.lo[axis] || lowHi < n.box.hi[axis]) ++a.notHeld;
            double tightLow, tightHigh;
            decodedBoth(g.origin[axis], g.step[axis], qlo + 1, tightLow, tightHigh);
            a.tighterWouldCut += tightHigh > n.box.lo[axis];
        }
        const int code = n.count > 0 ? kBvhLeafKinds * n.count + n.kind : 0;
        if (int(t[3]) != (n.first << kBvhBoxCodeBits | code)) ++a.wrongCode;
    }
    return a;
}

}  // namespace

TEST(BvhBoxes, EveryOneTexelBoxHoldsItsNode) {
    Scene far = demoScene("pro");
    for (Sphere& s : far.spheres) s.center += glm::dvec3(1e5 + 0.35, -1e5 - 0.123, 1e5 + 0.7);
    for (const auto& [name, scene] : {std::pair<const char*, Scene>{"pro", demoScene("pro")},
                                      {"lite", demoScene("lite")},
                                      {"pro 1e5 away", far}}) {
        const Bvh bvh = buildBvh(scene, 2, BvhObjects::SpheresAndMeshes);
        ASSERT_TRUE(bvhBoxesFit(bvh)) << name;
        const Audit a = audit(bvh);
        EXPECT_GT(a.nodes, 10) << name;
        EXPECT_EQ(a.notHeld, 0) << name;
        EXPECT_EQ(a.wrongCode, 0) << name;
        // The boxes are as tight as the grid allows: one step in would cut
        // some of them (so the containment above is not trivially true).
        EXPECT_GT(a.tighterWouldCut, 0) << name;
    }
}

// A tree whose items do not fit the texel's bits gets no one-texel nodes
// (the walk then reads the plain ones).
TEST(BvhBoxes, ATreeThatDoesNotFitGetsNone) {
    Bvh bvh;
    EXPECT_FALSE(bvhBoxesFit(bvh));
    bvh.nodes.resize(1);
    bvh.nodes[0].first = 1 << 20;  // first << 6 would pass 2^24
    bvh.nodes[0].count = 1;
    EXPECT_FALSE(bvhBoxesFit(bvh));
    std::vector<float> texels;
    appendBvhBoxTexels(bvh, texels);
    EXPECT_TRUE(texels.empty());
    EXPECT_TRUE(bvhBoxDefines(bvh).empty());
}
