#include "shell_slots.h"
#include "convex_shell.h"

#include <algorithm>
#include <cmath>

namespace raylab {

// variants/shared-work/08-full/find_closest.glsl's SHELL_GROUP spells out a
// shell's slots one by one, 6 of them: half a group's most triangles.
static_assert(kTriangleGroupMax / 2 <= 6, "find_closest.glsl's SHELL_GROUP tests 6 slots at most");

namespace {

// A face: the shell's triangles on one plane.
struct Face {
    glm::dvec3 normal;           // outward, unit
    glm::dvec3 point;            // on the plane
    std::vector<int> triangles;  // ascending
};

// The shell's faces: its triangles grouped by plane.
std::vector<Face> faces(const ConvexShell& shell) {
    std::vector<Face> out;
    for (std::size_t k = 0; k < shell.triangles.size(); ++k) {
        const glm::dvec3 n = shell.normals[k], p = shell.points[k];
        auto same = [&](const Face& f) {
            return glm::dot(f.normal, n) > 1.0 - 1e-12 &&
                   std::abs(glm::dot(f.normal, p - f.point)) <= shell.flat;
        };
        auto at = std::find_if(out.begin(), out.end(), same);
        if (at == out.end()) at = out.insert(out.end(), Face{n, p, {}});
        at->triangles.push_back(shell.triangles[k]);
    }
    return out;
}

// The shell's slots, or empty when a face has no opposite face of as many
// triangles.
std::vector<ShellSlot> slotsOf(const ConvexShell& shell) {
    std::vector<Face> all = faces(shell);
    std::vector<bool> paired(all.size(), false);
    std::vector<ShellSlot> slots;
    for (std::size_t a = 0; a < all.size(); ++a) {
        if (paired[a]) continue;
        std::size_t b = a + 1;
        while (b < all.size() &&
               (paired[b] || glm::dot(all[a].normal, all[b].normal) > -(1.0 - 1e-12)))
            ++b;
        if (b == all.size() || all[a].triangles.size() != all[b].triangles.size()) return {};
        paired[a] = paired[b] = true;
        const Face &top = all[a], &bottom = all[b];
        const glm::dvec3 n = top.normal;  // the bottom's plane too, in the top's normal
        for (std::size_t j = 0; j < top.triangles.size(); ++j)
            slots.push_back({n, glm::dot(n, top.point), glm::dot(n, bottom.point), top.triangles[j],
                             bottom.triangles[j]});
    }
    return slots;
}

}  // namespace

std::vector<std::vector<ShellSlot>> shellSlots(const Scene& scene,
                                               const std::vector<TriangleGroup>& groups) {
    std::vector<std::vector<ShellSlot>> out(groups.size());
    const std::vector<ConvexShell> shells = convexShells(scene);
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (const ConvexShell& shell : shells) {
            // The group must be the whole shell: its triangles, all of them.
            const bool whole = int(shell.triangles.size()) == groups[g].count &&
                               shell.triangles.front() == groups[g].first &&
                               shell.triangles.back() == groups[g].first + groups[g].count - 1;
            if (whole) out[g] = slotsOf(shell);
        }
    return out;
}

bool hasShellSlots(const Scene& scene, const std::vector<TriangleGroup>& groups) {
    for (const std::vector<ShellSlot>& slots : shellSlots(scene, groups))
        if (!slots.empty()) return true;
    return false;
}

}  // namespace raylab
