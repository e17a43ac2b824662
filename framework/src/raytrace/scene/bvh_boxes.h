#pragma once
// The BVH's nodes a second time, one texel each, for the eye-cells walk
// (framework/shaders/variants/eye-cells/08-full/test_spheres.glsl). The walk
// reads two children at every step; a texel read whose address differs
// between llvmpipe's 8 lock-step pixels is 8 loads, and a node of the
// plain layout (packedBvhNodes) is two texels. Here a node is one texel of
// the same texture, after the plain layout, so no renderer needs another
// texture (the web build's data textures included):
//   texel 2 * (nodeCount + n) = (lo.x | hi.x << 12, lo.y | hi.y << 12,
//                                lo.z | hi.z << 12, first << 6 | code)
// each a float holding an integer below 2^24 (exact), the box's corners in
// 12-bit steps of a grid over the root's box, rounded outwards: the boxes
// only grow, so the walk still finds every object the plain boxes let it
// find (and the nearest hit is the same). Texel 2 * (nodeCount + n) + 1 is
// unused, so the quantised node n is bvhNodeLow(nodeCount + n).
// (Header only: the renderer, the web build and the program's defines,
// stage_programs.cpp, share it.)
#include "bvh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace raylab {

inline constexpr int kBvhBoxBits = 12;
inline constexpr int kBvhBoxTop = (1 << kBvhBoxBits) - 1;  // the largest step index
inline constexpr int kBvhBoxCodeBits = 6;                  // a leaf's code: 8 * count + kind

struct BvhBoxGrid {
    float origin[3] = {0.0f, 0.0f, 0.0f};
    float step[3] = {1.0f, 1.0f, 1.0f};
};

// A float holds the integers below 2^24 exactly: `first` and a leaf's code
// (at most 2 items a leaf in the trees the eye cells use) must fit.
inline bool bvhBoxesFit(const Bvh& bvh) {
    if (bvh.nodes.empty()) return false;
    for (const BvhNode& n : bvh.nodes) {
        const int code = n.count > 0 ? kBvhLeafKinds * n.count + n.kind : 0;
        if (n.first < 0 || n.first >= (1 << (24 - kBvhBoxCodeBits)) ||
            code >= (1 << kBvhBoxCodeBits))
            return false;
    }
    return true;
}

// The grid: the root's box in a little under 2^12 steps a side, so that
// rounding outwards never runs past the last step.
inline BvhBoxGrid bvhBoxGrid(const Bvh& bvh) {
    BvhBoxGrid g;
    const BvhNode& root = bvh.nodes.front();
    const double lo[3] = {double(root.box.lo.x), double(root.box.lo.y), double(root.box.lo.z)};
    const double hi[3] = {double(root.box.hi.x), double(root.box.hi.y), double(root.box.hi.z)};
    for (int a = 0; a < 3; ++a) {
        g.origin[a] = float(lo[a]);
        if (double(g.origin[a]) > lo[a]) g.origin[a] = std::nextafter(g.origin[a], -INFINITY);
        const double extent = std::max(hi[a] - double(g.origin[a]), 1e-30);
        g.step[a] = float(extent / (kBvhBoxTop - 64));
    }
    return g;
}

namespace bvh_boxes_detail {

// What the GLSL makes of step index Q: origin + float(q) * step, with the
// multiply and the add rounded apart or fused.
inline void decoded(float origin, float step, int q, float& apart, float& fused) {
    volatile float product = float(q) * step;  // volatile: no contraction here
    apart = origin + product;
    fused = std::fma(float(q), step, origin);
}

// The step index whose decoded corner (either rounding) lies on V's outer
// side: at or below V for a box's minimum (DOWN), at or above it for its
// maximum; from the nearest guess outward, within [0, kBvhBoxTop].
inline int stepOutside(float origin, float step, double v, bool down) {
    const double guess = (v - double(origin)) / double(step);
    int q = int(std::clamp(down ? std::floor(guess) : std::ceil(guess), 0.0, double(kBvhBoxTop)));
    for (;;) {
        float apart, fused;
        decoded(origin, step, q, apart, fused);
        const bool outside = down ? double(apart) <= v && double(fused) <= v
                                  : double(apart) >= v && double(fused) >= v;
        if (outside || q == (down ? 0 : kBvhBoxTop)) return q;
        q += down ? -1 : 1;
    }
}

}  // namespace bvh_boxes_detail

// Appends the one-texel nodes to NODES, packedBvhNodes(bvh) (when they fit).
inline void appendBvhBoxTexels(const Bvh& bvh, std::vector<float>& nodes) {
    if (!bvhBoxesFit(bvh)) return;
    const BvhBoxGrid g = bvhBoxGrid(bvh);
    for (const BvhNode& n : bvh.nodes) {
        const double lo[3] = {double(n.box.lo.x), double(n.box.lo.y), double(n.box.lo.z)};
        const double hi[3] = {double(n.box.hi.x), double(n.box.hi.y), double(n.box.hi.z)};
        float texel[4];
        for (int a = 0; a < 3; ++a) {
            const int qlo = bvh_boxes_detail::stepOutside(g.origin[a], g.step[a], lo[a], true);
            const int qhi = bvh_boxes_detail::stepOutside(g.origin[a], g.step[a], hi[a], false);
            texel[a] = float(qlo | qhi << kBvhBoxBits);
        }
        const int code = n.count > 0 ? kBvhLeafKinds * n.count + n.kind : 0;
        texel[3] = float(n.first << kBvhBoxCodeBits | code);
        nodes.insert(nodes.end(), {texel[0], texel[1], texel[2], texel[3], 0.0f, 0.0f, 0.0f, 0.0f});
    }
}

// The program's defines for them: where they start (as a node index for
// bvhNodeLow) and the grid, as GLSL constants (%.9g: the same floats).
inline std::vector<std::string> bvhBoxDefines(const Bvh& bvh) {
    if (!bvhBoxesFit(bvh)) return {};
    const BvhBoxGrid g = bvhBoxGrid(bvh);
    auto vec3 = [](const float v[3]) {
        char text[128];
        std::snprintf(text, sizeof text, "vec3(%.9g, %.9g, %.9g)", double(v[0]), double(v[1]),
                      double(v[2]));
        return std::string(text);
    };
    return {"RAYLAB_BVH_BOXES " + std::to_string(bvh.nodes.size()),
            "RAYLAB_BVH_BOX_ORIGIN " + vec3(g.origin), "RAYLAB_BVH_BOX_STEP " + vec3(g.step)};
}

}  // namespace raylab
