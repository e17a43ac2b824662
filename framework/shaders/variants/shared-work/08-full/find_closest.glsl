// Variant of solution/08-full/find_closest.glsl, used instead of it when
// RAYLAB_SHARED_WORK is defined (the demo, and raylab bench's "shared"
// lever). Not part of any lab: students never see this file.
//
// The same searches; findClosest also keeps the pixel's first answer - its
// primary ray's - for the variant's glow.glsl, which asks the same question
// of the same ray.

// The nearest object along a ray, for the full demo. (Provided: nothing to
// do here, read it if you are curious.)
//
// Lab 05's findClosest tests every object for every ray. That is fine for a
// dozen objects; the pro scene has 110 spheres, a mesh from an OBJ file may
// have a hundred thousand triangles, and every shading point sends a shadow
// ray per light on top. Here the spheres and the meshes' triangles sit in
// a bounding volume hierarchy (BVH), built on the CPU
// (framework/src/raytrace/scene/bvh.cpp): a tree of boxes, each box holding
// its children. A ray that misses a box skips every object inside it. The
// few other objects (planes, the disc, the scene's own triangles, the
// torus) are tested one by one as in lab 05 - the triangles group by group,
// each group behind its box (framework/src/raytrace/scene/triangle_groups.h
// says why they are not in the tree).
//
// Why one kind per leaf: a CPU renderer such as llvmpipe runs 8 pixels in
// lock-step and executes both sides of an `if` whenever the pixels disagree.
// A leaf holding several kinds would need an `if` on the kind at every
// object, and every sphere test would pay for the other kind's code (tried
// with the torus: five times slower in an earlier version). So each leaf
// holds spheres only or mesh triangles only, and the triangle code is
// compiled only for scenes with meshes (RAYLAB_MESHES).
//
// GLSL has no recursion, so the tree is walked with a small stack of boxes
// still to visit - the same idea as trace()'s stack of rays. The nearer
// child is visited first; the farther one waits and is skipped when a hit
// nearer than its box has been found meanwhile.
//
// The walk is in test_spheres.glsl. Where the BVH is switched off (`raylab
// demo --no-bvh`, `raylab bench`, scenes with few spheres) the framework
// uses a test_spheres.glsl with lab 05's linear search instead.

void keepNearer(inout Hit hit, float t, int kind, int index)
{
    if (t != NO_HIT && t < hit.t) hit = Hit(t, objectId(kind, index));
}

#include "scene_meshes.glsl"
#include "test_spheres.glsl"
#include "triangle_shear.glsl"


// One group of the scene's triangles (scene_objects.glsl): skipped when the
// ray misses its box, or meets it only beyond the nearest hit.
void testTriangleGroup(Ray ray, vec3 invDir, TriangleShear shear, int g, inout Hit hit, bool stopAtFirst)
{
    if (stopAtFirst && hit.id >= 0) return;
    int first = int(uTriangleGroupLow[g].w), end = first + int(uTriangleGroupHigh[g].w);
    bool unrolled = false;
#if defined(SCENE_BAKED) && defined(RAYLAB_FRAGMENT_SHADER)
    // A zero the compiler cannot see: the group's bounds are constants in
    // the specialised program, and a loop of constant length would be
    // unrolled into all its triangle tests, run (masked) even where no
    // pixel's ray meets the group's box. A group of one or two triangles
    // (the mirror) is left to be unrolled: a turn of the loop costs about
    // two tests with constant corners, whose reads are 8 loads each.
    if (end - first > 2) end += int(gl_FragCoord.x < -1.0);
    else unrolled = true;
#endif
    // Not for an unrolled group: llvmpipe runs its tests (masked) whatever
    // the box says, so the box test would only cost.
    vec3 lo = uTriangleGroupLow[g].xyz, hi = uTriangleGroupHigh[g].xyz;
    vec3 pad = 1e-4 * (abs(lo) + abs(hi)) + 1e-5;  // rounding must not cut off a corner
    if (!unrolled && enterBox(ray.origin, invDir, lo - pad, hi + pad, hit.t) == T_FAR) return;
    for (int i = first; i < end && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectTriangleSheared(ray, shear, uTriangleVertices[3 * i], uTriangleVertices[3 * i + 1], uTriangleVertices[3 * i + 2]),
                   KIND_TRIANGLE, i);
}

#ifdef RAYLAB_SHELL_SLOTS
// A group that is a box-like shell (framework/src/raytrace/scene/
// shell_slots.h says why this finds the same first hit): of each pair of
// opposite faces only the plane a ray can meet the shell on first, so 6
// triangle tests for pro's glass cube, not 12. Every number here is a
// constant of the specialised program (the group's index, and the slots
// baked with the scene), so the tests have constant corners: no reads, and
// no box test, which would only cost (as for the unrolled groups above).
//
// Macros, not a function with a loop, so that every index below is a
// constant expression where it is written. Natively Mesa unrolls a loop
// over the slots either way; but a WebGL page's ANGLE clamps every index
// that is not a constant expression (a function's parameter, a loop's
// counter) before the driver sees it, and with the clamps Mesa no longer
// made the slots constants: the page's pro frame took 1.3x native's.

// Slot S (a constant expression; clamped so that a slot past the last,
// compiled but never run, still reads within the arrays). Going down
// (against the top's normal): the top if the ray crosses its plane beyond
// T_MIN, else the bottom; going up, the bottom if it crosses that plane
// beyond T_MIN, else the top. Both triangles' corners are constants:
// chosen, not read.
#define SHELL_SLOT(S) { \
        const int s_ = clamp(S, 0, uShellSlotPlane.length() - 1); \
        const vec4 plane = uShellSlotPlane[s_];   /* xyz: the top face's normal, w: its plane */ \
        const vec4 sides = uShellSlotSides[s_];   /* x: the bottom's plane; y, z: the triangles */ \
        const int t = int(sides.y), b = int(sides.z); \
        float at = dot(plane.xyz, ray.origin), along = dot(plane.xyz, ray.dir); \
        bool top = along < 0.0 ? at - plane.w > T_MIN * -along : sides.x - at <= T_MIN * along; \
        vec3 p0 = top ? uTriangleVertices[3 * t] : uTriangleVertices[3 * b]; \
        vec3 p1 = top ? uTriangleVertices[3 * t + 1] : uTriangleVertices[3 * b + 1]; \
        vec3 p2 = top ? uTriangleVertices[3 * t + 2] : uTriangleVertices[3 * b + 2]; \
        keepNearer(hit, intersectTriangleSheared(ray, shear, p0, p1, p2), KIND_TRIANGLE, top ? t : b); }

// The slots of group G (a constant expression): a group holds at most 12
// triangles (kTriangleGroupMax, triangle_groups.h), so a shell at most 6
// slots.
#define SHELL_SLOT_OF_GROUP(K) if (K < slots) SHELL_SLOT(slot + K)
#define SHELL_GROUP(G) { if (!(stopAtFirst && hit.id >= 0)) { \
        const int slot = uTriangleGroupSlot[G], slots = int(uTriangleGroupHigh[G].w) / 2; \
        SHELL_SLOT_OF_GROUP(0) SHELL_SLOT_OF_GROUP(1) SHELL_SLOT_OF_GROUP(2) \
        SHELL_SLOT_OF_GROUP(3) SHELL_SLOT_OF_GROUP(4) SHELL_SLOT_OF_GROUP(5) } }
#endif

// Every object but the spheres, one by one. With stopAtFirst it returns as
// soon as something nearer than hit.t is found.
void testOthers(Ray ray, inout Hit hit, bool stopAtFirst)
{
    for (int i = 0; i < uPlaneCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectPlane(ray, uPlanes[i].xyz, uPlanes[i].w), KIND_PLANE, i);
    for (int i = 0; i < uDiscCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectDisc(ray, uDiscs[i].xyz, uDiscNormals[i], uDiscs[i].w), KIND_DISC, i);
    vec3 invDir = inverseDirection(ray.dir);
    TriangleShear shear = triangleShear(ray.dir);  // once for all the triangles
#ifdef SCENE_BAKED
    // The groups one by one with constant indices, not in a loop: each
    // group's box and range are then constants of the program, not reads
    // (a read at an index the compiler cannot prove the same for all 8
    // lock-step pixels is 8 loads on llvmpipe). Groups past the eighth, if
    // any, in the loop.
#define GROUP_INDEX(G) max(min(G, uTriangleGroupCount - 1), 0)
#ifdef RAYLAB_SHELL_SLOTS
    // Which groups are shells is a constant too: each group compiles one
    // test or the other, not both.
#define TRIANGLE_GROUP(G) if (G < uTriangleGroupCount) { \
        if (uTriangleGroupSlot[GROUP_INDEX(G)] >= 0) SHELL_GROUP(GROUP_INDEX(G)) \
        else testTriangleGroup(ray, invDir, shear, GROUP_INDEX(G), hit, stopAtFirst); }
#else
#define TRIANGLE_GROUP(G) if (G < uTriangleGroupCount) testTriangleGroup(ray, invDir, shear, GROUP_INDEX(G), hit, stopAtFirst);
#endif
    TRIANGLE_GROUP(0) TRIANGLE_GROUP(1) TRIANGLE_GROUP(2) TRIANGLE_GROUP(3)
    TRIANGLE_GROUP(4) TRIANGLE_GROUP(5) TRIANGLE_GROUP(6) TRIANGLE_GROUP(7)
#undef TRIANGLE_GROUP
#undef GROUP_INDEX
    for (int g = 8; g < uTriangleGroupCount; ++g)
#else
    for (int g = 0; g < uTriangleGroupCount; ++g)
#endif
        testTriangleGroup(ray, invDir, shear, g, hit, stopAtFirst);
    for (int i = 0; i < uTorusCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectTorus(ray, i), KIND_TORUS, i);
}

Hit pixelFirstHit = Hit(T_FAR, -1);
bool pixelSearched = false;

bool findClosest(Ray ray, out Hit hit)
{
    hit = Hit(T_FAR, -1);
    testSpheres(ray, hit, false);
    testOthers(ray, hit, false);
    if (!pixelSearched) pixelFirstHit = hit;
    pixelSearched = true;
    return hit.id >= 0;
}

// Is any object nearer than maxT along the ray? For shadow rays: unlike
// findClosest it may stop at the first blocker it meets.
bool findBlocker(Ray ray, float maxT)
{
    Hit hit = Hit(maxT, -1);
    testSpheres(ray, hit, true);
    if (hit.id < 0) testOthers(ray, hit, true);
    return hit.id >= 0;
}
