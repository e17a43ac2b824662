// The triangles of the scene's OBJ meshes (stage 08, scenes with "meshes"),
// uploaded by the framework (framework/src/raytrace/scene_mesh_buffers.cpp). They
// sit in buffer textures, not uniform arrays: a mesh's count is limited by
// memory, not by uniform slots. All meshes' triangles are one list; a hit on
// triangle i has the id objectId(KIND_MESH, i). (Students need not change
// this file.) Compiled only for scenes that have meshes (RAYLAB_MESHES);
// other scenes get a stand-in that finds nothing, so that the BVH walk
// (test_spheres.glsl) reads the same for every scene and its mesh loop,
// which never runs there, compiles to nothing.
// Outside the #ifdef: a file is included once per program, wherever it
// first appears, so an #include inside it would vanish from other scenes.
#include "surface.glsl"
#include "mesh_access.glsl"  // meshTexel(k), meshMaterialOf(i); empty without meshes
#ifdef RAYLAB_MESHES

// Triangle i: texels 6i .. 6i+2 are its corners (position, u), texels
// 6i+3 .. 6i+5 their (unit normal, v); counter-clockwise from the front.
#ifndef SCENE_BAKED  // else a constant (framework/src/raytrace/scene/scene_baking.cpp)
uniform int uMeshTriangleCount;
#endif

vec3 meshCorner(int triangle, int k)
{
    return meshTexel(6 * triangle + k).xyz;
}

// The watertight test of intersect_triangle.glsl: neighbouring triangles of
// a mesh leave no crack between them.
float intersectMeshTriangle(Ray ray, int triangle)
{
    return intersectTriangle(ray, meshCorner(triangle, 0), meshCorner(triangle, 1), meshCorner(triangle, 2));
}

// The surface at POINT on mesh triangle I: the corners' normals and texture
// coordinates mixed by the point's barycentric weights (smooth shading).
Surface meshSurface(vec3 point, int i)
{
    vec4 p0 = meshTexel(6 * i), p1 = meshTexel(6 * i + 1), p2 = meshTexel(6 * i + 2);
    vec4 n0 = meshTexel(6 * i + 3), n1 = meshTexel(6 * i + 4), n2 = meshTexel(6 * i + 5);
    // Weights from the areas of the sub-triangles opposite each corner.
    vec3 face = cross(p1.xyz - p0.xyz, p2.xyz - p0.xyz);
    float area2 = dot(face, face);
    // The hit point back onto the triangle's plane before secondary rays
    // leave it, as surfaceAt does for the other kinds (from a far eye it
    // carries the eye's rounding).
    vec3 unitFace = face * inversesqrt(area2);
    point -= unitFace * dot(unitFace, point - p0.xyz);
    vec3 w = vec3(dot(cross(p2.xyz - p1.xyz, point - p1.xyz), face), dot(cross(p0.xyz - p2.xyz, point - p2.xyz), face),
                  dot(cross(p1.xyz - p0.xyz, point - p0.xyz), face)) / area2;
    vec3 normal = w.x * n0.xyz + w.y * n1.xyz + w.z * n2.xyz;
    // Opposite corner normals can cancel out: the face's normal then.
    normal = dot(normal, normal) > 1e-12 ? normalize(normal) : normalize(face);
    vec2 uv = w.x * vec2(p0.w, n0.w) + w.y * vec2(p1.w, n1.w) + w.z * vec2(p2.w, n2.w);
    Material material = materialAt(meshMaterialOf(i));
    if (material.texture >= 0) {
        vec3 picture = textureLayer(material.texture, uv).rgb;
        material.ambient *= picture;
        material.diffuse *= picture;
    }
    return Surface(point, normal, material, uv, vec3(0.0));
}
#else
float intersectMeshTriangle(Ray ray, int triangle)
{
    return NO_HIT;
}
#endif
