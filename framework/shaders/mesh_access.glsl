// Where scene_meshes.glsl reads the meshes' triangles from: two buffer
// textures (framework/src/raytrace/scene_mesh_buffers.cpp). The web build,
// which has no buffer textures, replaces this file with
// web/shaders/mesh_access.glsl. (Students need not read this file.)
#ifdef RAYLAB_MESHES  // (included outside it: see scene_meshes.glsl)
uniform samplerBuffer uMeshCorners;
uniform isamplerBuffer uMeshMaterials;  // per triangle: its mesh's material

vec4 meshTexel(int k)
{
    return texelFetch(uMeshCorners, k);
}

int meshMaterialOf(int triangle)
{
    return texelFetch(uMeshMaterials, triangle).r;
}
#endif
