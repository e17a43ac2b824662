// The nearest object along a ray, for the full demo. (Provided: nothing to
// do here, read it if you are curious.)
//
// Lab 05's findClosest tests every object for every ray. That is fine for a
// dozen objects; the pro scene has 110 spheres, and every shading point
// sends a shadow ray per light on top. Here the spheres sit in a bounding
// volume hierarchy (BVH), built on the CPU (framework/src/bvh.cpp): a tree
// of boxes, each box holding its children. A ray that misses a box skips
// every sphere inside it. The few other objects (planes, the disc, the
// triangles, the torus) are tested one by one as in lab 05.
//
// Why only spheres: a CPU renderer such as llvmpipe runs 8 pixels in
// lock-step and executes both sides of an `if` whenever the pixels disagree.
// A tree holding several kinds would need an `if` on the kind at every
// object, and every sphere test would pay for the torus's long code (tried:
// five times slower in an earlier version). One kind per tree keeps every test short.
//
// GLSL has no recursion, so the tree is walked with a small stack of boxes
// still to visit - the same idea as trace()'s stack of rays. The nearer
// child is visited first; the farther one waits and is skipped when a hit
// nearer than its box has been found meanwhile.
//
// The framework defines RAYLAB_BVH unless it is switched off (`raylab demo
// --no-bvh`, `raylab bench`); without it this is lab 05's linear search.

void keepNearer(inout Hit hit, float t, int kind, int index)
{
    if (t != NO_HIT && t < hit.t) hit = Hit(t, objectId(kind, index));
}

#ifdef RAYLAB_BVH
// Node n: texel 2n = (box min, first), texel 2n + 1 = (box max, count). A
// leaf (count > 0) holds the spheres uBvhItems[first .. first + count - 1];
// an inner node (count 0) has its children at nodes first and first + 1.
uniform samplerBuffer uBvhNodes;
uniform isamplerBuffer uBvhItems;
const int BVH_STACK_SIZE = 32;  // the tree's depth is checked on the CPU

// Where the ray enters the box lo..hi (0 when it starts inside), or T_FAR
// when it misses it or reaches it only beyond tMax (the slab test).
float enterBox(vec3 origin, vec3 invDir, vec3 lo, vec3 hi, float tMax)
{
    vec3 t0 = (lo - origin) * invDir;
    vec3 t1 = (hi - origin) * invDir;
    vec3 tNear = min(t0, t1);
    vec3 tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    return enter <= leave ? enter : T_FAR;
}

float enterNode(int node, vec3 origin, vec3 invDir, float tMax)
{
    return enterBox(origin, invDir, texelFetch(uBvhNodes, 2 * node).xyz, texelFetch(uBvhNodes, 2 * node + 1).xyz, tMax);
}

// Walks the tree, keeping the nearest sphere hit closer than hit.t. With
// anyHit it stops at the first sphere found (shadow rays need no more).
void walkBvh(Ray ray, inout Hit hit, bool anyHit)
{
    // 1/0 would give 0 * inf = NaN in the slab test for a ray exactly on a
    // box face: a tiny direction component instead gives a huge finite slope.
    vec3 d = ray.dir;
    vec3 invDir = 1.0 / vec3(abs(d.x) < 1e-20 ? 1e-20 : d.x, abs(d.y) < 1e-20 ? 1e-20 : d.y, abs(d.z) < 1e-20 ? 1e-20 : d.z);
    int stackNode[BVH_STACK_SIZE];
    float stackEnter[BVH_STACK_SIZE];
    int size = 0;
    int node = 0;
    if (enterNode(0, ray.origin, invDir, hit.t) == T_FAR) return;
    while (true) {
        int first = int(texelFetch(uBvhNodes, 2 * node).w);
        int count = int(texelFetch(uBvhNodes, 2 * node + 1).w);
        bool descend = false;
        if (count > 0) {
            for (int k = 0; k < count; ++k) {
                int i = texelFetch(uBvhItems, first + k).r;
                keepNearer(hit, intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w), KIND_SPHERE, i);
            }
            if (anyHit && hit.id >= 0) return;
        } else {
            float enterA = enterNode(first, ray.origin, invDir, hit.t);
            float enterB = enterNode(first + 1, ray.origin, invDir, hit.t);
            int near = enterA <= enterB ? first : first + 1;
            float enterFar = max(enterA, enterB);
            if (enterFar < T_FAR && size < BVH_STACK_SIZE) {
                stackNode[size] = near == first ? first + 1 : first;
                stackEnter[size] = enterFar;
                ++size;
            }
            if (min(enterA, enterB) < T_FAR) {
                node = near;
                descend = true;
            }
        }
        if (!descend) {
            // Next waiting box that could still hold something nearer.
            bool found = false;
            while (size > 0 && !found) {
                --size;
                if (stackEnter[size] < hit.t) {
                    node = stackNode[size];
                    found = true;
                }
            }
            if (!found) return;
        }
    }
}
#endif

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

void testSpheres(Ray ray, inout Hit hit, bool stopAtFirst)
{
#ifdef RAYLAB_BVH
    walkBvh(ray, hit, stopAtFirst);
#else
    for (int i = 0; i < uSphereCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w), KIND_SPHERE, i);
#endif
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
