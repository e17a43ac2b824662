// Variant of solution/08-full/find_closest.glsl, used instead of it when the
// framework defines RAYLAB_OLD_PATH (`raylab bench`, row old-path): the
// scene's triangles tested one by one, without their groups' boxes. Not
// part of any lab: students never see this file.
// The nearest object along a ray, for the full demo.
//
// Lab 05's findClosest tests every object for every ray. That is fine for a
// dozen objects; the pro scene has 110 spheres, a mesh from an OBJ file may
// have a hundred thousand triangles, and every shading point sends a shadow
// ray per light on top. Here the spheres and the meshes' triangles sit in
// a bounding volume hierarchy (BVH), built on the CPU
// (framework/src/raytrace/scene/bvh.cpp): a tree of boxes, each box holding
// its children. A ray that misses a box skips every object inside it. The
// few other objects (planes, the disc, the scene's own triangles, the
// torus) are tested one by one as in lab 05.
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


// Every object but the spheres, one by one. With stopAtFirst it returns as
// soon as something nearer than hit.t is found.
void testOthers(Ray ray, inout Hit hit, bool stopAtFirst)
{
    for (int i = 0; i < uPlaneCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectPlane(ray, uPlanes[i].xyz, uPlanes[i].w), KIND_PLANE, i);
    for (int i = 0; i < uDiscCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectDisc(ray, uDiscs[i].xyz, uDiscNormals[i], uDiscs[i].w), KIND_DISC, i);
    for (int i = 0; i < uTriangleCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectTriangle(ray, uTriangleVertices[3 * i], uTriangleVertices[3 * i + 1], uTriangleVertices[3 * i + 2]),
                   KIND_TRIANGLE, i);
    for (int i = 0; i < uTorusCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectTorus(ray, i), KIND_TORUS, i);
}


bool findClosest(Ray ray, out Hit hit)
{
    hit = Hit(T_FAR, -1);
    testSpheres(ray, hit, false);
    testOthers(ray, hit, false);
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
