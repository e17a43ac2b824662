//@open
//@ // The spheres and mesh triangles along a ray, found through the BVH (see
//@ // find_closest.glsl): the walk is yours (TODO 08.b).
//@guided
// The spheres and mesh triangles along a ray, found through the BVH (see
// find_closest.glsl). (Provided: nothing to do here.)
//@end-open
// The tree's nodes and items come from bvh_access.glsl: bvhNodeLow(n) is
// (box min, first), bvhNodeHigh(n) (box max, code). A leaf's code is 8 *
// count + the kind of its items (KIND_SPHERE or KIND_MESH): they are
// bvhItem(first) .. bvhItem(first + count - 1). An inner node (code 0) has
// its children at nodes first and first + 1.
#include "bvh_access.glsl"
#include "ray_box.glsl"

const int BVH_STACK_SIZE = 32;  // the tree's depth is checked on the CPU

// Where the ray enters node `node`'s box (T_FAR: misses it, or only beyond
// tMax). The node is read once: its `first` and `code` come out too, so the
// child visited next is not read again. Reads are dear on a CPU renderer:
// llvmpipe fetches 8 pixels' nodes one by one, and in pro the node reads
// were a quarter of a frame's instructions (this saved 6% of the frame).
float enterNode(int node, vec3 origin, vec3 invDir, float tMax, out int first, out int code)
{
    vec4 low = bvhNodeLow(node), high = bvhNodeHigh(node);
    first = int(low.w);
    code = int(high.w);
    return enterBox(origin, invDir, low.xyz, high.xyz, tMax);
}

// Walks the tree, keeping the nearest hit closer than hit.t. With anyHit it
// stops at the first object found (shadow rays need no more).
void walkBvh(Ray ray, inout Hit hit, bool anyHit)
{
    //@open
    //@ // TODO(08.b): the walk through the BVH.
    //@ // Walk the BVH from its root, node 0: keep in `hit` the nearest
    //@ // sphere (KIND_SPHERE) or mesh triangle (KIND_MESH) nearer than hit.t, with
    //@ // keepNearer, testing only the items of leaves whose box the ray enters
    //@ // before hit.t (enterNode); with anyHit, return as soon as hit.id >= 0.
    //@ //  - No recursion in GLSL: the boxes still to visit wait on a stack of your
    //@ //    own, at most BVH_STACK_SIZE deep (guide, section 5).
    //@ //  - Visit the nearer child first, and skip a waiting box that the ray
    //@ //    enters only beyond the nearest hit found meanwhile.
    //@ //  - Sphere i: intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w); mesh
    //@ //    triangle i: intersectMeshTriangle(ray, i).
    //@ // Checked by: raylab check --stage 08 (function walkBvh; views pro-front, pro-cube, mesh-front).
    //@ labTodo();
    //@guided
    vec3 invDir = inverseDirection(ray.dir);
    int stackNode[BVH_STACK_SIZE];
    float stackEnter[BVH_STACK_SIZE];
    int size = 0;
    int first, code;  // of the node being visited
    if (enterNode(0, ray.origin, invDir, hit.t, first, code) == T_FAR) return;
    while (true) {
        // Down to the next leaf, then its objects: two loops one after the
        // other, not one loop with an `if` for "inner node or leaf". The 8
        // lock-step pixels of llvmpipe are at different nodes; with the
        // `if`, every step would run both sides for all 8. This way they
        // walk inner nodes together, then test leaves together (Aila and
        // Laine's "while-while"; about a tenth faster on pro).
        while (code == 0) {
            int firstA, codeA, firstB, codeB;
            float enterA = enterNode(first, ray.origin, invDir, hit.t, firstA, codeA);
            float enterB = enterNode(first + 1, ray.origin, invDir, hit.t, firstB, codeB);
            bool nearA = enterA <= enterB;
            float enterFar = max(enterA, enterB);
            if (enterFar < T_FAR && size < BVH_STACK_SIZE) {
                stackNode[size] = nearA ? first + 1 : first;
                stackEnter[size] = enterFar;
                ++size;
            }
            if (min(enterA, enterB) == T_FAR) break;  // both missed: next waiting box
            first = nearA ? firstA : firstB;
            code = nearA ? codeA : codeB;
        }
        // A leaf (unless both children were missed: code 0, count 0): one
        // of these loops runs, the one of its kind.
        int count = code / 8, kind = code - 8 * count;
        for (int k = 0; k < (kind == KIND_SPHERE ? count : 0); ++k) {
            int i = bvhItem(first + k);
            keepNearer(hit, intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w), KIND_SPHERE, i);
        }
        for (int k = 0; k < (kind == KIND_MESH ? count : 0); ++k) {
            int i = bvhItem(first + k);
            keepNearer(hit, intersectMeshTriangle(ray, i), KIND_MESH, i);
        }
        if (anyHit && hit.id >= 0) return;
        // Next waiting box that could still hold something nearer. (A
        // shadow ray's boxes all can: its hit.t stays the light's distance,
        // the limit they were pushed under, until it stops.)
        bool found = false;
        int node = 0;
        while (size > 0 && !found) {
            --size;
            if (anyHit || stackEnter[size] < hit.t) {
                node = stackNode[size];
                found = true;
            }
        }
        if (!found) return;
        first = int(bvhNodeLow(node).w);
        code = int(bvhNodeHigh(node).w);
    }
    //@end-open
}

// Keeps the nearest sphere or mesh-triangle hit closer than hit.t; with
// stopAtFirst it may stop at the first one found.
void testSpheres(Ray ray, inout Hit hit, bool stopAtFirst)
{
    walkBvh(ray, hit, stopAtFirst);
}
