// The ray tracer, without recursion. GLSL has no recursive calls, so the
// rays that still have to be followed wait on a small stack.
//
// At a glass surface one ray becomes two: the reflected one and the
// refracted one. The refracted ray is pushed on the stack with its weight;
// the reflected ray is followed at once. When a path ends (a matte surface,
// the sky, or the depth limit), the next waiting ray is popped. When the
// stack is empty, the pixel is done.
#include "ray_offset.glsl"

uniform int uMaxDepth;  // rays per path, 1..MAX_DEPTH (arrow keys; MAX_DEPTH = 8 is defined by the framework)

// A ray waiting to be traced.
struct PendingRay {
    Ray ray;
    vec3 weight;  // how much of its colour reaches the pixel
    int depth;    // rays on its path so far, itself included (primary ray: 1)
};

// Secondary rays start just off the surface, on the side they leave from:
// offsetRayOrigin(point, side) (framework/shaders/ray_offset.glsl, see lab 03).

// Every ray ends its path or splits in two, at most MAX_DEPTH - 1 times:
// MAX_RAYS = 2^MAX_DEPTH (defined by the framework) bounds the rays of one
// pixel, and keeps the loop finite.

vec3 trace(Ray primary)
{
    // Pending rays on one path have different depths 2..MAX_DEPTH, so
    // MAX_DEPTH entries are always enough.
    PendingRay stack[MAX_DEPTH];
    int stackSize = 0;
    vec3 color = vec3(0.0);
    PendingRay current = PendingRay(primary, vec3(1.0), 1);

    for (int n = 0; n < MAX_RAYS; ++n) {
        bool pathGoesOn = false;
        Hit hit;
        if (!findClosest(current.ray, hit)) {
            color += current.weight * skyColor(current.ray.dir);  // escaped to the sky
        } else {
            Surface s = surfaceAt(current.ray, hit);
            vec3 point = s.point;
            bool entering = dot(current.ray.dir, s.normal) < 0.0;
            vec3 normal = entering ? s.normal : -s.normal;  // faces the incoming ray
            Material m = s.material;
            color += current.weight * blinnPhong(point, normal, -current.ray.dir, m);

            if (m.type != MAT_PLASTIC && current.depth < uMaxDepth) {
                float cosIncident = -dot(current.ray.dir, normal);
                vec3 reflectance;  // the share of light the reflected ray carries
                if (m.type == MAT_MIRROR) {
                    reflectance = m.specular;
                } else if (m.type == MAT_METAL) {
                    reflectance = fresnelConductor(cosIncident, m.n, m.k);
                } else {
                    vec4 glass = refractGlass(current.ray.dir, normal, entering, m.ior);
                    float F = glass.w;
                    if (glass.xyz != vec3(0.0) && stackSize < MAX_DEPTH) {
                        stack[stackSize] = PendingRay(Ray(offsetRayOrigin(point, -normal), glass.xyz),
                                                      current.weight * (1.0 - F), current.depth + 1);
                        ++stackSize;
                    }
                    reflectance = vec3(F);
                }
                current = PendingRay(Ray(offsetRayOrigin(point, normal), reflect(current.ray.dir, normal)),
                                     current.weight * reflectance, current.depth + 1);
                pathGoesOn = true;
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
