// Variant of solution/05-primitives/surface_at.glsl for stage 08 scenes with
// OBJ meshes (the framework defines RAYLAB_MESHES): the same, plus mesh
// triangles, whose surface scene_meshes.glsl works out (interpolated normal
// and texture coordinates, the point put back onto the triangle's plane).
// Not part of any lab: students never see this file. Keep it in step with
// the original (tests/unit/shader_variants_test.cpp compares the two).
#include "surface_detail.glsl"

Surface surfaceAt(Ray ray, Hit hit)
{
    vec3 point = ray.origin + hit.t * ray.dir;
    int kind = objectKind(hit.id);
    int i = objectIndex(hit.id);
    if (kind == KIND_MESH) return meshSurface(point, i);
    vec3 normal;
    int material;
    // The hit point ray.origin + t dir carries the rounding of the origin
    // and of t: from a far eye it lies float steps of the eye's coordinates
    // off the surface, more than offsetRayOrigin's steps of the point's own
    // (tests/numerics/offset_test.cpp, "floor from afar"). So it is put back
    // onto the surface first (pbrt does the same), from the object's own
    // numbers; the torus keeps its polished hit.
    if (kind == KIND_SPHERE) {
        normal = normalize(point - uSpheres[i].xyz);
        point = uSpheres[i].xyz + uSpheres[i].w * normal;
        material = uSphereMaterial[i];
    } else if (kind == KIND_PLANE) {
        normal = uPlanes[i].xyz;
        point -= normal * (dot(normal, point) - uPlanes[i].w);
        material = uPlaneMaterial[i];
    } else if (kind == KIND_DISC) {
        normal = uDiscNormals[i];
        point -= normal * dot(normal, point - uDiscs[i].xyz);
        material = uDiscMaterial[i];
    } else if (kind == KIND_TRIANGLE) {
        // Counter-clockwise corners: the cross product points to the front.
        vec3 a = uTriangleVertices[3 * i];
        normal = normalize(cross(uTriangleVertices[3 * i + 1] - a, uTriangleVertices[3 * i + 2] - a));
        point -= normal * dot(normal, point - a);
        material = uTriangleMaterial[i];
    } else {
        normal = torusNormal(i, point);
        material = uTorusMaterial[i];
    }
    Surface s = Surface(point, normal, materialAt(material), vec2(0.0), vec3(0.0));
    addSurfaceDetail(s, kind, i);
    return s;
}
