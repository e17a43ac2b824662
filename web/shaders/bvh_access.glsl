// The web build's BVH storage (WebGL 2 has no buffer textures): the same
// three functions as framework/shaders/bvh_access.glsl, over 2D textures
// filled row by row (texel_rows.glsl). Put in front of the
// search path, it replaces the native file; test_spheres.glsl is unchanged.
// (Students need not change this file.)
#include "texel_rows.glsl"
uniform highp sampler2D uBvhNodes;
uniform highp isampler2D uBvhItems;

vec4 bvhNodeLow(int node)
{
    return texelFetch(uBvhNodes, dataTexel(2 * node), 0);
}

vec4 bvhNodeHigh(int node)
{
    return texelFetch(uBvhNodes, dataTexel(2 * node + 1), 0);
}

int bvhItem(int k)
{
    return texelFetch(uBvhItems, dataTexel(k), 0).r;
}
