// Variant of solution/08-full/test_spheres.glsl, used instead of it when
// RAYLAB_EYE_CELLS is defined (the demo, and raylab bench's "eye" lever).
// Not part of any lab: students never see this file.
//
// The same walk, except where the ray starts at the point the eye's cells
// were built around (every primary ray): its cell's list of spheres
// (framework/src/raytrace/scene/eye_cells.h) is the one leaf it tests, in
// place of the walk from the root. The lists sit in the tree's own item
// texture, after the tree's items, so the leaf loop reads them unchanged.
// Conservative lists, so the nearest hit is the walk's, bit for bit.
// The spheres and mesh triangles along a ray, found through the BVH (see
// find_closest.glsl). (Provided: nothing to do here.)
// The tree's nodes and items come from bvh_access.glsl: bvhNodeLow(n) is
// (box min, first), bvhNodeHigh(n) (box max, code). A leaf's code is 8 *
// count + the kind of its items (KIND_SPHERE or KIND_MESH): they are
// bvhItem(first) .. bvhItem(first + count - 1). An inner node (code 0) has
// its children at nodes first and first + 1.
#include "bvh_access.glsl"
#include "ray_box.glsl"
#include "cube_cell.glsl"
#include "eye_cell_access.glsl"  // eyeCellList(cell): (first, count) of its spheres in the tree's items

uniform int uEyeCellsSize;         // cells along a cube face's edge
uniform vec3 uEyeCellsCentre;      // the point the cells were built around: the eye

// The stack holds at most one node per level of the tree: sized to the
// tree's depth (stage_programs.cpp), not to the deepest tree any scene may
// have. A shorter stack is cheaper where locals are zero-filled for every
// ray (WebGL: ANGLE does it; pro 193 -> 162 ms a frame in the page).
#ifdef RAYLAB_BVH_STACK_SIZE
const int BVH_STACK_SIZE = RAYLAB_BVH_STACK_SIZE;
#else
const int BVH_STACK_SIZE = 32;  // the tree's depth is checked on the CPU
#endif

// Where the ray enters node `node`'s box (T_FAR: misses it, or only beyond
// tMax). The node is read once: its `first` and `code` come out too, so the
// child visited next is not read again. Reads are dear on a CPU renderer:
// llvmpipe fetches 8 pixels' nodes one by one, and in pro the node reads
// were a quarter of a frame's instructions (this saved 6% of the frame).
float enterNode(int node, vec3 origin, vec3 invDir, float tMax, out int first, out int code)
{
#ifdef RAYLAB_BVH_BOXES
    // The node's one-texel copy (framework/src/raytrace/scene/bvh_boxes.h):
    // its box in 12-bit steps of a grid over the root's box, rounded
    // outwards, and its first and code. One read instead of two.
    ivec4 q = ivec4(bvhNodeLow(RAYLAB_BVH_BOXES + node));
    vec3 lo = RAYLAB_BVH_BOX_ORIGIN + vec3(q.xyz & 0xfff) * RAYLAB_BVH_BOX_STEP;
    vec3 hi = RAYLAB_BVH_BOX_ORIGIN + vec3(q.xyz >> 12) * RAYLAB_BVH_BOX_STEP;
    first = q.w >> 6;
    code = q.w & 63;
    return enterBox(origin, invDir, lo, hi, tMax);
#else
    vec4 low = bvhNodeLow(node), high = bvhNodeHigh(node);
    first = int(low.w);
    code = int(high.w);
    return enterBox(origin, invDir, low.xyz, high.xyz, tMax);
#endif
}

// A waiting node on the stack: its `first` and `code` in one int, not its
// index (the pop would read the node again). A code is 8 * count + kind
// with at most 2 spheres a leaf here (eye cells: spheres only, at most
// kEyeCellMaxSpheres), far below 1024; `first` stays below 2^21.
const int NODE_CODE_BITS = 10;
const int NODE_CODE_MASK = (1 << NODE_CODE_BITS) - 1;
int packNode(int first, int code)
{
    return (first << NODE_CODE_BITS) | code;
}

// Walks the tree, keeping the nearest hit closer than hit.t. With anyHit it
// stops at the first object found (shadow rays need no more).
void walkBvh(Ray ray, inout Hit hit, bool anyHit)
{
    vec3 invDir = inverseDirection(ray.dir);
    int stackNode[BVH_STACK_SIZE];
    float stackEnter[BVH_STACK_SIZE];
    int size = 0;
    int first, code;  // of the node being visited
    float enterRoot = enterNode(0, ray.origin, invDir, hit.t, first, code);
    // A ray from the eye: its cell's list is the leaf. (The same 8 pixels
    // all start there or none does: a primary ray is every pixel's first.)
    if (ray.origin == uEyeCellsCentre) {
        ivec2 list = eyeCellList(cubeCell(ray.dir, uEyeCellsSize));
        first = list.x;
        // An empty list: a leaf of planes, a kind no leaf holds, tests nothing.
        code = list.y > 0 ? 8 * list.y + KIND_SPHERE : KIND_PLANE;
    } else if (enterRoot == T_FAR) {
        return;
    }
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
                // The far child's `first` and `code`, packed: popping it
                // needs no read of its node (two fetches of 8 pixels each).
                stackNode[size] = nearA ? packNode(firstB, codeB) : packNode(firstA, codeA);
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
            vec4 sphere = uSpheres[i];  // one read: WebGL clamps every indexed read
            keepNearer(hit, intersectSphere(ray, sphere.xyz, sphere.w), KIND_SPHERE, i);
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
        int waiting = 0;
        while (size > 0 && !found) {
            --size;
            if (anyHit || stackEnter[size] < hit.t) {
                waiting = stackNode[size];
                found = true;
            }
        }
        if (!found) return;
        first = waiting >> NODE_CODE_BITS;
        code = waiting & NODE_CODE_MASK;
    }
}

// Keeps the nearest sphere or mesh-triangle hit closer than hit.t; with
// stopAtFirst it may stop at the first one found.
void testSpheres(Ray ray, inout Hit hit, bool stopAtFirst)
{
    walkBvh(ray, hit, stopAtFirst);
}
