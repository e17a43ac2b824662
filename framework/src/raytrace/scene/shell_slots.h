#pragma once
// A triangle group (triangle_groups.h) that is a whole closed convex shell
// whose faces come in parallel, opposite pairs - a box such as pro's glass
// cube - needs only half its triangles tested in a nearest-hit search.
//
// Why: take one pair of opposite faces, the "top" with outward normal n on
// the plane n.x = top, the "bottom" on n.x = bottom < top. A nearest-hit
// search wants the first point beyond T_MIN where a ray meets the shell:
// where it enters it (an origin outside) or leaves it (an origin inside, or
// outside but crossing the surface before T_MIN). A ray going down
// (n.d < 0) can enter this pair's slab only through the top, and can meet
// the top's plane beyond T_MIN only if it starts above it by more than
// T_MIN (-n.d). If it does, the top is its only way in and the bottom comes
// after; if not, it is in the slab (or crossing into it too soon to count)
// and can only leave through the bottom. So of the two faces one is chosen
// by that test (going up, the mirror image), and a face left out could only
// have been met after the first point, where a nearest-hit search no longer
// looks.
//
// The specialised demo program (RAYLAB_SHELL_SLOTS; variants/shared-work/
// 08-full/find_closest.glsl's SHELL_GROUP) tests a shell by its slots:
// one slot per triangle of a top face, holding that triangle and the bottom
// face's triangle across from it; each pixel's ray picks one of the two.
// The slots are constants of the program, spelt out as 6 tests with
// constant corners for pro's cube (a group, kTriangleGroupMax, holds at
// most 12 triangles, so a shell at most 6 slots), where the group's loop took
// 12 turns of reads (llvmpipe reads an index that differs between its 8
// lock-step pixels 8 times over). The picture stays the same (the demo's
// views to the byte: tests/e2e/bvh_images_test.cpp's
// ShellSlotsDrawWhatEveryTriangleDraws).
//
// Rounding: the GPU makes the choice in float, and the triangle test finds
// its own t; the two can disagree only for a crossing within rounding of
// T_MIN itself, a ray that meets the plane about T_MIN from its origin
// (every ray that leaves the shell's own faces is moved 256 float steps to
// the side it goes to, ray_offset.glsl, and is not one of them).
// tests/unit/shell_slots_test.cpp sends rays from the eye, the spheres, both
// sides of the shell's faces, inside and around it, and finds the first hit
// of the 12 triangles among the slots' 6. (Students need not read this file.)
#include "scene.h"
#include "triangle_groups.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct ShellSlot {
    glm::dvec3 normal{0.0};  // the top face's outward unit normal
    double top = 0.0;        // the top face's plane: normal . x = top
    double bottom = 0.0;     // the bottom face's plane: normal . x = bottom
    int topTriangle = 0;     // index into scene.triangles
    int bottomTriangle = 0;
};

// For each group, its slots: half as many as its triangles, the top faces'
// triangles in order; empty where the group is not such a shell.
std::vector<std::vector<ShellSlot>> shellSlots(const Scene& scene,
                                               const std::vector<TriangleGroup>& groups);

// Whether any of the groups is such a shell.
bool hasShellSlots(const Scene& scene, const std::vector<TriangleGroup>& groups);

}  // namespace raylab
