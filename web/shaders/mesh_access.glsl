// The web build's mesh storage (WebGL 2 has no buffer textures): the same
// two functions as framework/shaders/mesh_access.glsl, over 2D textures
// filled row by row (texel_rows.glsl).
#include "texel_rows.glsl"
#ifdef RAYLAB_MESHES  // (included outside it: see scene_meshes.glsl)
uniform highp sampler2D uMeshCorners;
uniform highp isampler2D uMeshMaterials;  // per triangle: its mesh's material

vec4 meshTexel(int k)
{
    return texelFetch(uMeshCorners, dataTexel(k), 0);
}

int meshMaterialOf(int triangle)
{
    return texelFetch(uMeshMaterials, dataTexel(triangle), 0).r;
}
#endif
