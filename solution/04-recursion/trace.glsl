//@open
//@ // The ray tracer: every ray a pixel's primary ray leads to, by reflection
//@ // and refraction, up to a depth limit. GLSL has no recursive calls.
//@guided
// The ray tracer, without recursion. GLSL has no recursive calls, so the
// rays that still have to be followed wait on a small stack.
//
// At a glass surface one ray becomes two: the reflected one and the
// refracted one. The refracted ray is pushed on the stack with its weight;
// the reflected ray is followed at once. When a path ends (a matte surface,
// the sky, or the depth limit), the next waiting ray is popped. When the
// stack is empty, the pixel is done.
//@end-open
#include "ray_offset.glsl"

uniform int uMaxDepth;  // rays per path, 1..MAX_DEPTH (arrow keys; MAX_DEPTH = 8 is defined by the framework)

//@open
//@ // TODO(04.a): the colour the primary ray brings to its pixel.
//@ // That is the Blinn-Phong colour of its hit (or skyColor of its direction when it
//@ // hits nothing), plus, at a mirror, metal or glass surface (m.type not
//@ // MAT_PLASTIC), the colour of the reflected ray times the surface's
//@ // reflectance (mirror: m.specular; metal: fresnelConductor), and at glass
//@ // also the colour of the refracted ray (refractGlass), each weighted by the
//@ // share of light it carries - and so on for the rays they make.
//@ //  - GLSL has no recursion: follow one ray at a time and keep the rays still
//@ //    to follow on a stack of your own (an array and its size; the guide's
//@ //    section 1 says how deep it must be).
//@ //  - A path has at most uMaxDepth rays (the primary ray counts as one); the
//@ //    loop must end for every pixel: bound it by MAX_RAYS.
//@ //  - A ray leaving a surface starts just off it, on the side it leaves
//@ //    toward (offsetRayOrigin, as in lab 03): a refracted ray starts inside.
//@ //  - surfaceAt(ray, hit) gives a Surface: .point (where the ray hit),
//@ //    .normal (unit, out of the object) and .material, a Material: .type
//@ //    (MAT_PLASTIC, MAT_MIRROR, MAT_GLASS or MAT_METAL), .specular (a
//@ //    mirror's reflectance), .ior (glass), .n and .k (metal). Shade with the
//@ //    normal facing the incoming ray.
//@ // Checked by: raylab check --stage 04 (function trace; views front, depth-1, depth-2, glass-closeup, inside-glass, gold).
//@ vec3 trace(Ray primary)
//@ {
//@     labTodo();
//@     return vec3(0.0);
//@ }
//@guided
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
                    // TODO(04.b): glass. refractGlass (fresnel.glsl, TODO 04.e) gives
                    // the refracted direction and the share F of the light that is
                    // reflected. Unless nothing is refracted (total internal
                    // reflection: the direction is vec3(0.0)), push the refracted ray
                    // - it starts just INSIDE the surface it crosses, at
                    // offsetRayOrigin(point, -normal) - with weight
                    // current.weight * (1 - F). The reflected ray carries F.
                    // Checked by: raylab check --stage 04 (views front, glass-closeup, inside-glass; trace).
                    //@solution
                    vec4 glass = refractGlass(current.ray.dir, normal, entering, m.ior);
                    float F = glass.w;
                    if (glass.xyz != vec3(0.0) && stackSize < MAX_DEPTH) {
                        stack[stackSize] = PendingRay(Ray(offsetRayOrigin(point, -normal), glass.xyz),
                                                      current.weight * (1.0 - F), current.depth + 1);
                        ++stackSize;
                    }
                    reflectance = vec3(F);
                    //@stub
                    //@ labTodo();
                    //@ reflectance = vec3(1.0);  // placeholder: glass as a perfect mirror
                    //@end
                }
                current = PendingRay(Ray(offsetRayOrigin(point, normal), reflect(current.ray.dir, normal)),
                                     current.weight * reflectance, current.depth + 1);
                pathGoesOn = true;
            }
        }

        if (!pathGoesOn) {
            // TODO(04.a): this path has ended. Continue with the ray on top
            // of the stack, or stop when the stack is empty.
            // Checked by: raylab check --stage 04 (views front, inside-glass; trace).
            //@solution
            if (stackSize == 0) break;
            --stackSize;
            current = stack[stackSize];
            //@stub
            //@ labTodo();
            //@ break;
            //@end
        }
    }
    return color;
}
//@end-open
