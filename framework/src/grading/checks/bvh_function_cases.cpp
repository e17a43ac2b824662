// Stage 08's walkBvh, checked in small worlds of spheres: each world's BVH
// is built here (leaves of at most two spheres, children next to each other
// as the framework lays them out, bvh_access.glsl) and handed to the harness
// as arrays behind bvhNodeLow, bvhNodeHigh and bvhItem. The reference is the
// nearest sphere by brute force, in double precision: a walk that skips a
// box it should visit, reads a child or a leaf's items wrongly, or stops too
// early finds another sphere or none.
#include "bvh_function_cases.h"

#include "function_compare.h"

#ifndef RAYLAB_REFERENCES_AS_DATA  // the references: not in the page's core or a student build
#include "reference_intersect.h"
#endif
#include "shader_constants.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace raylab {

namespace {

using glm::dvec3;
using glm::dvec4;

struct BvhWorld {
    const char* name;
    std::vector<dvec4> spheres;  // centre, radius
};

const std::vector<BvhWorld>& bvhWorlds() {
    static const std::vector<BvhWorld> all = [] {
        BvhWorld row{"eight spheres in a row along x", {}};
        for (int i = 0; i < 8; ++i)
            row.spheres.push_back(
                dvec4(3.0 * i - 10.5, 0.3 * std::sin(i), -0.2 * i, 0.6 + 0.1 * (i % 3)));
        return std::vector<BvhWorld>{
            row,
            {"a cluster of overlapping spheres",
             {{0, 0, 0, 1.2},
              {0.8, 0.3, 0.2, 0.9},
              {-0.7, 0.5, -0.3, 0.8},
              {0.2, -0.9, 0.4, 0.7},
              {0.1, 0.2, 1.1, 0.6},
              {-0.4, -0.3, -1.0, 0.9},
              {1.5, -0.2, -0.6, 0.5}}},
            {"small spheres inside a big one",
             {{0, 0, 0, 10},
              {2, 1, -3, 0.5},
              {-3, 0.5, 2, 0.7},
              {1, -2, 4, 0.6},
              {-1, 3, -5, 0.8},
              {4, 0, 0, 1}}},
        };
    }();
    return all;
}

struct Node {
    dvec3 lo, hi;
    int first = 0, code = 0;  // as bvh_access.glsl: a leaf's code is 8 * count + kind
};

#ifndef RAYLAB_REFERENCES_AS_DATA  // the stand-ins' worlds: not in the page's core or a student
                                   // build
struct Bvh {
    std::vector<Node> nodes;
    std::vector<int> items;
};

// Median split on the longest axis of the centres, leaves of one or two
// spheres; an inner node's children are nodes first and first + 1.
void buildNode(const std::vector<dvec4>& spheres, std::vector<int> ids, std::size_t at, Bvh& bvh) {
    Node& n = bvh.nodes[at];
    n.lo = dvec3(1e30);
    n.hi = dvec3(-1e30);
    dvec3 clo(1e30), chi(-1e30);
    for (int i : ids) {
        const dvec3 c(spheres[std::size_t(i)]);
        const double r = spheres[std::size_t(i)].w;
        n.lo = glm::min(n.lo, c - r);
        n.hi = glm::max(n.hi, c + r);
        clo = glm::min(clo, c);
        chi = glm::max(chi, c);
    }
    // A little room, so that rounding the box to float cuts off no sphere.
    const dvec3 pad = 1e-5 * (glm::abs(n.lo) + glm::abs(n.hi)) + 1e-6;
    n.lo -= pad;
    n.hi += pad;
    if (ids.size() <= 2) {
        n.first = int(bvh.items.size());
        n.code = 8 * int(ids.size()) + shader::kSphere;
        bvh.items.insert(bvh.items.end(), ids.begin(), ids.end());
        return;
    }
    const dvec3 extent = chi - clo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    std::sort(ids.begin(), ids.end(), [&](int a, int b) {
        return spheres[std::size_t(a)][axis] < spheres[std::size_t(b)][axis];
    });
    const std::size_t child = bvh.nodes.size();
    bvh.nodes[at].first = int(child);
    bvh.nodes[at].code = 0;
    bvh.nodes.resize(child + 2);
    const auto half = ids.begin() + std::ptrdiff_t(ids.size() / 2);
    buildNode(spheres, std::vector<int>(ids.begin(), half), child, bvh);
    buildNode(spheres, std::vector<int>(half, ids.end()), child + 1, bvh);
}

Bvh buildBvh(const std::vector<dvec4>& spheres) {
    Bvh bvh;
    bvh.nodes.resize(1);
    std::vector<int> ids(spheres.size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = int(i);
    buildNode(spheres, ids, 0, bvh);
    return bvh;
}

std::string glsl(const dvec4& v) {
    return "vec4(" + glslFloat(v.x) + ", " + glslFloat(v.y) + ", " + glslFloat(v.z) + ", " +
           glslFloat(v.w) + ")";
}

// loadWorld(w): the world's spheres and its tree into the stand-in arrays.
std::string bvhWorldsGlsl() {
    std::size_t spheres = 0, nodes = 0, items = 0;
    std::vector<Bvh> trees;
    for (const BvhWorld& w : bvhWorlds()) {
        trees.push_back(buildBvh(w.spheres));
        spheres = std::max(spheres, w.spheres.size());
        nodes = std::max(nodes, trees.back().nodes.size());
        items = std::max(items, trees.back().items.size());
    }
    std::string text = "vec4 uSpheres[" + std::to_string(spheres) + "];\n" + "vec4 gNodeLow[" +
                       std::to_string(nodes) + "], gNodeHigh[" + std::to_string(nodes) + "];\n" +
                       "int gItems[" + std::to_string(items) + "];\n" +
                       "void loadWorld(int world)\n{\n";
    for (std::size_t w = 0; w < trees.size(); ++w) {
        text += std::string(w ? "    } else " : "    ") + "if (world == " + std::to_string(w) +
                ") {  // " + bvhWorlds()[w].name + "\n";
        const std::vector<dvec4>& s = bvhWorlds()[w].spheres;
        for (std::size_t i = 0; i < s.size(); ++i)
            text += "        uSpheres[" + std::to_string(i) + "] = " + glsl(s[i]) + ";\n";
        for (std::size_t n = 0; n < trees[w].nodes.size(); ++n) {
            const Node& node = trees[w].nodes[n];
            text += "        gNodeLow[" + std::to_string(n) +
                    "] = " + glsl(dvec4(node.lo, node.first)) + ";\n        gNodeHigh[" +
                    std::to_string(n) + "] = " + glsl(dvec4(node.hi, node.code)) + ";\n";
        }
        for (std::size_t k = 0; k < trees[w].items.size(); ++k)
            text += "        gItems[" + std::to_string(k) +
                    "] = " + std::to_string(trees[w].items[k]) + ";\n";
    }
    return text + "    }\n}\n";
}

const char* kBvhPrelude =
    "#include \"ray.glsl\"\n"
    "#include \"scene_objects.glsl\"  // objectId and KIND_*\n"
    "#include \"bvh_access.glsl\"     // its texture reads are replaced below\n"
    "#define bvhNodeLow(n) gNodeLow[n]\n"
    "#define bvhNodeHigh(n) gNodeHigh[n]\n"
    "#define bvhItem(k) gItems[k]\n";
#endif

// a0: the ray's origin, a0.w the world; a1: its unit direction, a1.w 1 for
// anyHit; a2.x the hit distance the walk starts with (< 0: T_FAR).
FunctionCase walkCase(int world, dvec3 origin, dvec3 toward, bool anyHit = false,
                      double limit = -1.0) {
    const dvec3 dir = glm::normalize(toward);
    std::string label = std::string(bvhWorlds()[std::size_t(world)].name) + ", ray from (" +
                        caseNumber(origin.x) + ", " + caseNumber(origin.y) + ", " +
                        caseNumber(origin.z) + ") along (" + caseNumber(dir.x) + ", " +
                        caseNumber(dir.y) + ", " + caseNumber(dir.z) + ")";
    if (limit > 0.0) label += ", hit.t " + caseNumber(limit) + " to begin with";
    if (anyHit) label += ", anyHit";
    return caseOf(std::move(label), dvec4(origin, world), dvec4(dir, anyHit ? 1.0 : 0.0),
                  dvec4(limit, 0, 0, 0));
}

std::string sphereHitText(const dvec4& v) {
    return v.x > 0.5 ? "sphere " + std::to_string(std::lround(v.z)) + " at t = " + caseNumber(v.y)
                     : std::string("no hit");
}

}  // namespace

FunctionSpec walkBvhSpec() {
    FunctionSpec s;
    s.name = "walkBvh";
    s.prelude = RAYLAB_HARNESS_GLSL(
        kBvhPrelude + bvhWorldsGlsl() +
        "#include \"intersect_sphere.glsl\"\n"
        "// Stand-ins for find_closest.glsl's keepNearer and the meshes (none here).\n"
        "void keepNearer(inout Hit hit, float t, int kind, int index)\n"
        "{\n"
        "    if (t != NO_HIT && t < hit.t) hit = Hit(t, objectId(kind, index));\n"
        "}\n"
        "float intersectMeshTriangle(Ray ray, int triangle) { return NO_HIT; }\n");
    s.includes = {"test_spheres.glsl"};
    s.defines = {"RAYLAB_BVH"};
    s.helpers =
        RAYLAB_HARNESS_GLSL("vec4 checkWalkBvh(vec4 a0, vec4 a1, vec4 a2)\n"
                            "{\n"
                            "    loadWorld(int(a0.w));\n"
                            "    Hit hit = Hit(a2.x > 0.0 ? a2.x : T_FAR, -1);\n"
                            "    walkBvh(Ray(a0.xyz, a1.xyz), hit, a1.w > 0.5);\n"
                            "    return vec4(hit.id >= 0 ? 1.0 : 0.0, hit.t, float(hit.id), 1.0);\n"
                            "}\n");
    s.call = "checkWalkBvh(a0, a1, a2)";
    const dvec3 o(0.0);
    s.cases = {
        walkCase(0, {-20, 0.1, -0.7}, {1, 0, 0}),
        walkCase(0, {20, 0.1, -0.7}, {-1, 0, 0}),
        walkCase(0, {-1.6, 5, -0.6}, {0, -1, 0}),
        walkCase(0, {-20, 3, 0}, {1, 0, 0}),
        walkCase(0, {-14, -2, 1}, {1, 0.1, -0.12}),
        walkCase(0, {12, 4, -6}, {-0.6, -0.25, 0.3}),
        walkCase(0, {20, 0.1, -0.7}, {-1, 0, 0}, false, 5.0),
        walkCase(0, {20, 0.1, -0.7}, {-1, 0, 0}, true, 12.0),
        walkCase(0, {20, 0.1, -0.7}, {-1, 0, 0}, true, 5.0),
        walkCase(1, {5, 0.2, 0.1}, {-1, 0, 0}),
        walkCase(1, {-5, -0.3, -0.9}, {1, 0, 0.05}),
        walkCase(1, {0.3, 4, 1.0}, {0, -1, 0}),
        walkCase(1, o, {1, 0, 0}),
        walkCase(1, o, {-0.2, -0.3, -1}),
        walkCase(1, {0.1, 0.2, 5}, {0, 0, -1}, true),
        walkCase(2, o, {2, 1, -3}),
        walkCase(2, o, {-3, 0.5, 2}),
        walkCase(2, o, {1, -2, 4}),
        walkCase(2, o, {0, 1, 0}),
        walkCase(2, {0, 0, 20}, {0, 0, -1}),
        walkCase(2, {-1, 3, 10}, {0, 0, -1}),
        walkCase(2, o, {4, 0, 0}, false, 2.5),
        walkCase(2, o, {4, 0, 0}, true, 3.5),
    };
    RAYLAB_REFERENCE(s, [](const FunctionCase& c) {
        const std::vector<dvec4>& spheres = bvhWorlds()[std::size_t(c.in[0].w)].spheres;
        const reference::DRay ray{dvec3(asHarnessReads(c.in[0])), dvec3(asHarnessReads(c.in[1]))};
        dvec4 best(0.0, c.in[2].x > 0.0 ? c.in[2].x : shader::kTFar, -1.0, 1.0);
        for (std::size_t i = 0; i < spheres.size(); ++i) {
            const double t = reference::intersectSphere(ray, dvec3(spheres[i]), spheres[i].w);
            if (t != reference::kNoHit && t < best.y) best = dvec4(1.0, t, double(i), 1.0);
        }
        return best;
    });
    s.compare = [](const FunctionCase& c, const dvec4& got, const dvec4& want) -> std::string {
        if (!allFinite(got)) return c.label + ": got NaN or Inf";
        const bool anyHit = c.in[1].w > 0.5, found = got.x > 0.5;
        bool same = found == (want.x > 0.5);
        if (same && found && anyHit)  // any sphere before the limit will do
            same = got.y < (c.in[2].x > 0.0 ? c.in[2].x : shader::kTFar);
        else if (same && found)
            same = std::lround(got.z) == std::lround(want.z) &&
                   std::fabs(got.y - want.y) <= 1e-4 * std::max(1.0, want.y);
        return same ? ""
                    : c.label + ": expected " +
                          (anyHit && found ? "a sphere before the limit" : sphereHitText(want)) +
                          ", got " + sphereHitText(got);
    };
    return s;
}

}  // namespace raylab
