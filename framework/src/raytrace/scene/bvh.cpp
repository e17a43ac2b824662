#include "bvh.h"

#include "error.h"
#include "float_rounding.h"
#include "shader_constants.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab {

double Aabb::area() const {
    const glm::dvec3 e = hi - lo;
    if (e.x < 0.0 || e.y < 0.0 || e.z < 0.0) return 0.0;
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

bool Aabb::contains(const Aabb& b) const {
    return glm::all(glm::lessThanEqual(lo, b.lo)) && glm::all(glm::greaterThanEqual(hi, b.hi));
}

namespace {

// Pad a little: float rounding in the GLSL slab test must never cut off a
// surface that touches the box.
Aabb padded(Aabb box) {
    const glm::dvec3 pad = 1e-4 * (glm::abs(box.lo) + glm::abs(box.hi)) + glm::dvec3(1e-5);
    box.lo -= pad;
    box.hi += pad;
    return box;
}

}  // namespace

Aabb sphereBounds(const Scene& scene, int index) {
    const Sphere& s = scene.spheres.at(std::size_t(index));
    const glm::dvec3 sweep = glm::abs(glm::dvec3(s.motion.axis)) * std::fabs(s.motion.amplitude);
    return padded(
        {s.center - glm::dvec3(s.radius) - sweep, s.center + glm::dvec3(s.radius) + sweep});
}

std::array<glm::dvec3, 3> meshTriangleCorners(const Scene& scene, int index) {
    std::size_t i = std::size_t(index);
    for (const MeshObject& m : scene.meshes) {
        if (i < m.triangleCount()) return {m.corner(i, 0), m.corner(i, 1), m.corner(i, 2)};
        i -= m.triangleCount();
    }
    throw Error("mesh triangle " + std::to_string(index) + " does not exist");
}

Aabb triangleBounds(const Scene& scene, int index) {
    Aabb box;
    for (const glm::dvec3& p : scene.triangles.at(std::size_t(index)).vertices) box.grow(p);
    return padded(box);
}

// A disc of radius r and unit normal n reaches r * sqrt(1 - n_i^2) from its
// centre along axis i (0 along its normal, r across it).
Aabb discBounds(const Scene& scene, int index) {
    const Disc& d = scene.discs.at(std::size_t(index));
    const glm::dvec3 n(d.normal);
    const glm::dvec3 reach = d.radius * glm::sqrt(glm::max(glm::dvec3(1.0) - n * n, 0.0));
    return padded({d.center - reach, d.center + reach});
}

Aabb meshTriangleBounds(const Scene& scene, int index) {
    Aabb box;
    for (const glm::dvec3& p : meshTriangleCorners(scene, index)) box.grow(p);
    return padded(box);
}

namespace {

struct Builder {
    const int maxLeaf;
    std::vector<Aabb> boxes;  // per item
    std::vector<glm::dvec3> centres;
    std::vector<int> kinds;    // per item: KIND_SPHERE, KIND_MESH, KIND_TRIANGLE or KIND_DISC
    std::vector<int> indices;  // per item: index in its kind's list
    std::vector<int> order;    // item numbers, partitioned in place
    std::vector<BvhNode> nodes;
    int depth = 0;

    Aabb boundsOf(int begin, int end) const {
        Aabb b;
        for (int i = begin; i < end; ++i) b.grow(boxes[std::size_t(order[std::size_t(i)])]);
        return b;
    }

    static constexpr int kBins = 12;

    // The bin of ITEM's centre along AXIS within the centres' box.
    int binOf(int item, int axis, const Aabb& centreBox) const {
        const double lo = centreBox.lo[axis], hi = centreBox.hi[axis];
        const int b = int(double(kBins) * (centres[std::size_t(item)][axis] - lo) / (hi - lo));
        return std::clamp(b, 0, kBins - 1);
    }

    // Binned SAH split of items [begin, end): partitions them and returns the
    // split position, or -1 when keeping them in one leaf is cheaper (and
    // allowed).
    int split(int begin, int end, const Aabb& box, int level) {
        const int n = end - begin;
        // Several kinds here: the first item's kind to one side, the others
        // to the other (leaves hold one kind, see bvh.h).
        const int firstKind = kinds[std::size_t(order[std::size_t(begin)])];
        auto sameKind = [&](int item) { return kinds[std::size_t(item)] == firstKind; };
        auto byKind = std::partition(order.begin() + begin, order.begin() + end, sameKind);
        if (byKind != order.begin() + end) return int(byKind - order.begin());
        // Too few levels left for an area split that might be lopsided: halve.
        const double leaves = std::ceil(double(n) / double(maxLeaf));
        if (n > maxLeaf && std::log2(leaves) + 1.0 >= double(kBvhMaxDepth - level))
            return halve(begin, end);
        Aabb centreBox;
        for (int i = begin; i < end; ++i)
            centreBox.grow(centres[std::size_t(order[std::size_t(i)])]);
        double bestCost = std::numeric_limits<double>::max();
        int bestAxis = -1, bestBin = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (centreBox.hi[axis] - centreBox.lo[axis] < 1e-12) continue;
            Aabb bins[kBins];
            int counts[kBins] = {};
            for (int i = begin; i < end; ++i) {
                int item = order[std::size_t(i)];
                int b = binOf(item, axis, centreBox);
                bins[b].grow(boxes[std::size_t(item)]);
                ++counts[b];
            }
            for (int cut = 1; cut < kBins; ++cut) {
                Aabb left, right;
                int nl = 0, nr = 0;
                for (int b = 0; b < cut; ++b) {
                    if (counts[b]) left.grow(bins[b]);
                    nl += counts[b];
                }
                for (int b = cut; b < kBins; ++b) {
                    if (counts[b]) right.grow(bins[b]);
                    nr += counts[b];
                }
                if (nl == 0 || nr == 0) continue;
                const double cost = left.area() * double(nl) + right.area() * double(nr);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = cut;
                }
            }
        }
        if (bestAxis < 0)
            return n <= maxLeaf ? -1 : begin + n / 2;  // all centres equal: split by count
        // Cost of a leaf vs. of traversing two children (box test ~ 1 object test).
        if (n <= maxLeaf && box.area() * double(n) <= box.area() + bestCost) return -1;
        auto mid = std::partition(order.begin() + begin, order.begin() + end, [&](int item) {
            return binOf(item, bestAxis, centreBox) < bestBin;
        });
        return int(mid - order.begin());
    }

    // Splits [begin, end) at its middle along the widest axis of the centres.
    int halve(int begin, int end) {
        Aabb centreBox;
        for (int i = begin; i < end; ++i)
            centreBox.grow(centres[std::size_t(order[std::size_t(i)])]);
        const glm::dvec3 e = centreBox.hi - centreBox.lo;
        int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        int mid = begin + (end - begin) / 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](int a, int b) {
                             const double ca = centres[std::size_t(a)][axis];
                             const double cb = centres[std::size_t(b)][axis];
                             return ca < cb || (ca == cb && a < b);
                         });
        return mid;
    }

    void build(int nodeIndex, int begin, int end, int level) {
        depth = std::max(depth, level);
        if (level > kBvhMaxDepth)
            throw Error("BVH deeper than " + std::to_string(kBvhMaxDepth) +
                        " levels: degenerate scene?");
        Aabb box = boundsOf(begin, end);
        nodes[std::size_t(nodeIndex)].box = box;
        int mid = end - begin <= 1 ? -1 : split(begin, end, box, level);
        if (mid < 0) {
            nodes[std::size_t(nodeIndex)].first = begin;
            nodes[std::size_t(nodeIndex)].count = end - begin;
            nodes[std::size_t(nodeIndex)].kind = kinds[std::size_t(order[std::size_t(begin)])];
            return;
        }
        int left = int(nodes.size());
        nodes.emplace_back();
        nodes.emplace_back();
        nodes[std::size_t(nodeIndex)].first = left;
        nodes[std::size_t(nodeIndex)].count = 0;
        build(left, begin, mid, level + 1);
        build(left + 1, mid, end, level + 1);
    }
};

}  // namespace

Bvh buildBvh(const Scene& scene, int maxLeaf, BvhObjects objects) {
    Bvh bvh;
    Builder b{std::max(1, maxLeaf), {}, {}, {}, {}, {}, {}};
    auto add = [&](int kind, int index, const Aabb& box) {
        b.boxes.push_back(box);
        b.centres.push_back(box.centre());
        b.kinds.push_back(kind);
        b.indices.push_back(index);
        b.order.push_back(int(b.order.size()));
    };
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        add(shader::kSphere, int(i), sphereBounds(scene, int(i)));
    // Corner by corner, without meshTriangleBounds' search through the meshes.
    int triangle = 0;
    for (const MeshObject& m : scene.meshes)
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            Aabb box;
            for (std::size_t k = 0; k < 3; ++k) box.grow(m.corner(t, k));
            add(shader::kMesh, triangle++, padded(box));
        }
    if (objects == BvhObjects::AllBounded) {
        for (std::size_t i = 0; i < scene.triangles.size(); ++i)
            add(shader::kTriangle, int(i), triangleBounds(scene, int(i)));
        for (std::size_t i = 0; i < scene.discs.size(); ++i)
            add(shader::kDisc, int(i), discBounds(scene, int(i)));
    }
    if (b.order.empty()) return bvh;
    b.nodes.emplace_back();
    b.build(0, 0, int(b.order.size()), 1);
    bvh.nodes = std::move(b.nodes);
    for (int item : b.order) bvh.items.push_back(b.indices[std::size_t(item)]);
    bvh.depth = b.depth;
    return bvh;
}

std::vector<float> packedBvhNodes(const Bvh& bvh) {
    std::vector<float> nodes;
    for (const BvhNode& n : bvh.nodes) {
        const glm::vec3 lo = floatBelow(n.box.lo), hi = floatAbove(n.box.hi);
        nodes.insert(nodes.end(), {lo.x, lo.y, lo.z, float(n.first)});
        const int code = n.count > 0 ? kBvhLeafKinds * n.count + n.kind : 0;
        nodes.insert(nodes.end(), {hi.x, hi.y, hi.z, float(code)});
    }
    if (nodes.empty()) nodes.assign(8, 0.0f);
    return nodes;
}

}  // namespace raylab
