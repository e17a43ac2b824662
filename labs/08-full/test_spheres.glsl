// The spheres and mesh triangles along a ray, found through the BVH (see
// find_closest.glsl). (Provided: nothing to do here.)
// The tree's nodes and items come from bvh_access.glsl: bvhNodeLow(n) is
// (box min, first), bvhNodeHigh(n) (box max, count). A leaf (count > 0)
// holds the spheres bvhItem(first) .. bvhItem(first + count - 1), a leaf
// with count < 0 the mesh triangles bvhItem(first) .. bvhItem(first -
// count - 1); an inner node (count 0) has its children at nodes first and
// first + 1.
#include "bvh_access.glsl"

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
    return enterBox(origin, invDir, bvhNodeLow(node).xyz, bvhNodeHigh(node).xyz, tMax);
}

// Walks the tree, keeping the nearest hit closer than hit.t. With anyHit it
// stops at the first object found (shadow rays need no more).
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
        int first = int(bvhNodeLow(node).w);
        int count = int(bvhNodeHigh(node).w);
        bool descend = false;
        if (count != 0) {
            // One of these two loops runs: count < 0 for mesh triangles.
            for (int k = 0; k < -count; ++k) {
                int i = bvhItem(first + k);
                keepNearer(hit, intersectMeshTriangle(ray, i), KIND_MESH, i);
            }
            for (int k = 0; k < count; ++k) {
                int i = bvhItem(first + k);
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

// Keeps the nearest sphere or mesh-triangle hit closer than hit.t; with
// stopAtFirst it may stop at the first one found.
void testSpheres(Ray ray, inout Hit hit, bool stopAtFirst)
{
    walkBvh(ray, hit, stopAtFirst);
}
