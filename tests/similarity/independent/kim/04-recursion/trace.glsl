// The ray tracer: every ray a pixel's primary ray leads to, by reflection
// and refraction, up to a depth limit. GLSL has no recursive calls.
#include "ray_offset.glsl"

uniform int uMaxDepth;  // rays per path, 1..MAX_DEPTH (arrow keys; MAX_DEPTH = 8 is defined by the framework)

// TODO(04.a): the colour the primary ray brings to its pixel.
// That is the Blinn-Phong colour of its hit (or skyColor of its direction when it
// hits nothing), plus, at a mirror, metal or glass surface (m.type not
// MAT_PLASTIC), the colour of the reflected ray times the surface's
// reflectance (mirror: m.specular; metal: fresnelConductor), and at glass
// also the colour of the refracted ray (refractGlass), each weighted by the
// share of light it carries - and so on for the rays they make.
//  - GLSL has no recursion: follow one ray at a time and keep the rays still
//    to follow on a stack of your own (an array and its size; the guide's
//    section 1 says how deep it must be).
//  - A path has at most uMaxDepth rays (the primary ray counts as one); the
//    loop must end for every pixel: bound it by MAX_RAYS.
//  - A ray leaving a surface starts just off it, on the side it leaves
//    toward (offsetRayOrigin, as in lab 03): a refracted ray starts inside.
//  - surfaceAt(ray, hit) gives the hit's point, outward normal and material;
//    shade with the normal facing the incoming ray.
// Checked by: raylab check --stage 04 (views front, depth-1, depth-2, glass-closeup, inside-glass, gold).
struct Job { Ray r; vec3 w; int d; };

vec3 trace(Ray primary)
{
    Job todo[MAX_DEPTH];
    int top = 0;
    Job j = Job(primary, vec3(1.0), 1);
    vec3 sum = vec3(0.0);
    int steps = 0;
    while (steps < MAX_RAYS) {
        steps++;
        Hit h;
        bool more = false;
        if (findClosest(j.r, h)) {
            Surface s = surfaceAt(j.r, h);
            bool outside = dot(j.r.dir, s.normal) < 0.0;
            vec3 n = outside ? s.normal : -s.normal;
            sum += j.w * blinnPhong(s.point, n, -j.r.dir, s.material);
            if (s.material.type != MAT_PLASTIC && j.d < uMaxDepth) {
                vec3 k;
                if (s.material.type == MAT_MIRROR) k = s.material.specular;
                else if (s.material.type == MAT_METAL) k = fresnelConductor(-dot(j.r.dir, n), s.material.n, s.material.k);
                else {
                    vec4 g = refractGlass(j.r.dir, n, outside, s.material.ior);
                    if (g.xyz != vec3(0.0) && top < MAX_DEPTH) {
                        todo[top] = Job(Ray(offsetRayOrigin(s.point, -n), g.xyz), j.w * (1.0 - g.w), j.d + 1);
                        top++;
                    }
                    k = vec3(g.w);
                }
                j = Job(Ray(offsetRayOrigin(s.point, n), reflect(j.r.dir, n)), j.w * k, j.d + 1);
                more = true;
            }
        } else {
            sum += j.w * skyColor(j.r.dir);
        }
        if (!more) {
            if (top <= 0) return sum;
            top--;
            j = todo[top];
        }
    }
    return sum;
}
