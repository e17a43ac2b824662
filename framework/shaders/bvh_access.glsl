// Where the BVH of stage 08 is stored, behind three functions, so that the
// file that walks it (test_spheres.glsl) reads the same on every target:
// here the nodes and items are buffer textures; WebGL 2 has none, and a web
// build keeps them in 2D textures behind the same three functions.
// (Students need not change this file.)
//
// Node n: (box min, first) and (box max, code). A leaf's code is 8 * count
// + kind: it holds the objects bvhItem(first) .. bvhItem(first + count - 1)
// of that kind (KIND_SPHERE, KIND_MESH, KIND_TRIANGLE or KIND_DISC); an
// inner node (code 0) has its children at nodes first and first + 1.
uniform samplerBuffer uBvhNodes;
uniform isamplerBuffer uBvhItems;

vec4 bvhNodeLow(int node)
{
    return texelFetch(uBvhNodes, 2 * node);
}

vec4 bvhNodeHigh(int node)
{
    return texelFetch(uBvhNodes, 2 * node + 1);
}

int bvhItem(int k)
{
    return texelFetch(uBvhItems, k).r;
}
