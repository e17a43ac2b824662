// Pictures on surfaces: texture coordinates for spheres, planes and discs,
// and the material's texture applied to them. (Provided; the TODOs are in
// sphere_uv.glsl and plane_uv.glsl.)
#include "sphere_uv.glsl"
#include "plane_uv.glsl"
#include "normal_map.glsl"

void addSurfaceDetail(inout Surface s, int kind, int index)
{
    if (kind == KIND_SPHERE) {
        vec3 d = normalize(s.point - uSpheres[index].xyz);
        s.uv = sphereUV(d);
        s.tangent = sphereTangent(d);
    } else if (kind == KIND_PLANE) {
        s.uv = planeUV(s.point, uPlanes[index].xyz * uPlanes[index].w, s.normal, uPlaneTileSize[index]);
    } else if (kind == KIND_DISC) {
        // The picture spans the disc once, centred.
        float diameter = 2.0 * uDiscs[index].w;
        s.uv = planeUV(s.point, uDiscs[index].xyz, s.normal, diameter) + 0.5;
    }
    if (s.material.texture >= 0) {
        vec3 picture = textureLayer(s.material.texture, s.uv).rgb;
        s.material.ambient *= picture;
        s.material.diffuse *= picture;
    }
    applyNormalMap(s);
}
