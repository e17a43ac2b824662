// Variant of solution/04-recursion/trace.glsl, used instead of it when
// RAYLAB_WEIGHT_CUT is defined (raylab bench's "weight-cut" lever).
// Not part of any lab: students never see this file.
//
// The same tracer, except that a reflected or refracted ray whose weight
// is below RAYLAB_WEIGHT_CUT in every channel is not traced. Such a ray
// could add at most its weight times the brightest colour its path gathers,
// so the error is bounded by the cut; in pro most of those rays are the
// few percent that glass reflects, bouncing on inside the cube.
#include "ray_offset.glsl"

uniform int uMaxDepth;

struct PendingRay {
    Ray ray;
    vec3 weight;
    int depth;
};

bool weightCounts(vec3 weight)
{
    return max(weight.r, max(weight.g, weight.b)) >= float(RAYLAB_WEIGHT_CUT);
}

vec3 trace(Ray primary)
{
    PendingRay stack[MAX_DEPTH];
    int stackSize = 0;
    vec3 color = vec3(0.0);
    PendingRay current = PendingRay(primary, vec3(1.0), 1);

    for (int n = 0; n < MAX_RAYS; ++n) {
        bool pathGoesOn = false;
        Hit hit;
        if (!findClosest(current.ray, hit)) {
            color += current.weight * skyColor(current.ray.dir);
        } else {
            Surface s = surfaceAt(current.ray, hit);
            vec3 point = s.point;
            bool entering = dot(current.ray.dir, s.normal) < 0.0;
            vec3 normal = entering ? s.normal : -s.normal;
            Material m = s.material;
            color += current.weight * blinnPhong(point, normal, -current.ray.dir, m);

            if (m.type != MAT_PLASTIC && current.depth < uMaxDepth) {
                float cosIncident = -dot(current.ray.dir, normal);
                vec3 reflectance;
                if (m.type == MAT_MIRROR) {
                    reflectance = m.specular;
                } else if (m.type == MAT_METAL) {
                    reflectance = fresnelConductor(cosIncident, m.n, m.k);
                } else {
                    vec4 glass = refractGlass(current.ray.dir, normal, entering, m.ior);
                    float F = glass.w;
                    vec3 refractedWeight = current.weight * (1.0 - F);
                    if (glass.xyz != vec3(0.0) && stackSize < MAX_DEPTH &&
                        weightCounts(refractedWeight)) {
                        stack[stackSize] = PendingRay(Ray(offsetRayOrigin(point, -normal), glass.xyz),
                                                      refractedWeight, current.depth + 1);
                        ++stackSize;
                    }
                    reflectance = vec3(F);
                }
                vec3 reflectedWeight = current.weight * reflectance;
                if (weightCounts(reflectedWeight)) {
                    current = PendingRay(Ray(offsetRayOrigin(point, normal), reflect(current.ray.dir, normal)),
                                         reflectedWeight, current.depth + 1);
                    pathGoesOn = true;
                }
            }
        }

        if (!pathGoesOn) {
            if (stackSize == 0) break;
            --stackSize;
            current = stack[stackSize];
        }
    }
    return color;
}
