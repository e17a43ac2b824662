// Variant of solution/08-full/test_spheres.glsl, used instead of it when the
// framework does not define RAYLAB_BVH (`raylab demo --no-bvh`, `raylab
// bench`, scenes with few spheres): lab 05's linear search.
// Not part of any lab: students never see this file.
#include "ray_box.glsl"  // for find_closest.glsl's groups of triangles

void testSpheres(Ray ray, inout Hit hit, bool stopAtFirst)
{
    for (int i = 0; i < uSphereCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w), KIND_SPHERE, i);
#ifdef RAYLAB_MESHES
    for (int i = 0; i < uMeshTriangleCount && !(stopAtFirst && hit.id >= 0); ++i)
        keepNearer(hit, intersectMeshTriangle(ray, i), KIND_MESH, i);
#endif
}
