// The web build's BVH storage (WebGL 2 has no buffer textures): the same
// three functions as framework/shaders/bvh_access.glsl, over 2D textures
// BVH_TEXTURE_WIDTH texels wide, filled row by row. Put in front of the
// search path, it replaces the native file; test_spheres.glsl is unchanged.
// (Students need not change this file.)
uniform highp sampler2D uBvhNodes;
uniform highp isampler2D uBvhItems;

const int BVH_TEXTURE_WIDTH = 1024;

ivec2 bvhTexel(int i)
{
    return ivec2(i % BVH_TEXTURE_WIDTH, i / BVH_TEXTURE_WIDTH);
}

vec4 bvhNodeLow(int node)
{
    return texelFetch(uBvhNodes, bvhTexel(2 * node), 0);
}

vec4 bvhNodeHigh(int node)
{
    return texelFetch(uBvhNodes, bvhTexel(2 * node + 1), 0);
}

int bvhItem(int k)
{
    return texelFetch(uBvhItems, bvhTexel(k), 0).r;
}
