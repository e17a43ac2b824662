// Variant of solution/05-primitives/surface_at.glsl for stage 08 scenes with
// OBJ meshes (the framework defines RAYLAB_MESHES): the same, plus mesh
// triangles, whose surface scene_meshes.glsl works out (interpolated normal
// and texture coordinates). Not part of any lab: students never see this file.
#include "surface_detail.glsl"

Surface surfaceAt(Ray ray, Hit hit)
{
    vec3 point = ray.origin + hit.t * ray.dir;
    int kind = objectKind(hit.id);
    int i = objectIndex(hit.id);
    if (kind == KIND_MESH) return meshSurface(point, i);
    vec3 normal;
    int material;
    if (kind == KIND_SPHERE) {
        normal = normalize(point - uSpheres[i].xyz);
        material = uSphereMaterial[i];
    } else if (kind == KIND_PLANE) {
        normal = uPlanes[i].xyz;
        material = uPlaneMaterial[i];
    } else if (kind == KIND_DISC) {
        normal = uDiscNormals[i];
        material = uDiscMaterial[i];
    } else if (kind == KIND_TRIANGLE) {
        // Counter-clockwise corners: the cross product points to the front.
        vec3 a = uTriangleVertices[3 * i];
        normal = normalize(cross(uTriangleVertices[3 * i + 1] - a, uTriangleVertices[3 * i + 2] - a));
        material = uTriangleMaterial[i];
    } else {
        normal = torusNormal(i, point);
        material = uTorusMaterial[i];
    }
    Surface s = Surface(point, normal, materialAt(material), vec2(0.0), vec3(0.0));
    addSurfaceDetail(s, kind, i);
    return s;
}
