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
// My ray stack: each waiting ray with how much it still counts and its depth.
Ray waitingRays[MAX_DEPTH];
vec3 waitingWeights[MAX_DEPTH];
int waitingDepths[MAX_DEPTH];
int waitingCount;

void pushRay(Ray r, vec3 weight, int depth)
{
    if (waitingCount >= MAX_DEPTH) return;  // cannot happen: depths differ
    waitingRays[waitingCount] = r;
    waitingWeights[waitingCount] = weight;
    waitingDepths[waitingCount] = depth;
    waitingCount = waitingCount + 1;
}

vec3 reflectanceOf(Material mat, float cosine)
{
    if (mat.type == MAT_MIRROR) {
        return mat.specular;
    }
    return fresnelConductor(cosine, mat.n, mat.k);
}

vec3 trace(Ray primary)
{
    waitingCount = 0;
    vec3 pixel = vec3(0.0);
    Ray ray = primary;
    vec3 weight = vec3(1.0);
    int depth = 1;
    for (int iteration = 0; iteration < MAX_RAYS; iteration = iteration + 1) {
        Hit closest;
        bool continues = false;
        bool hitSomething = findClosest(ray, closest);
        if (hitSomething == false) {
            pixel = pixel + weight * skyColor(ray.dir);
        }
        if (hitSomething) {
            Surface surf = surfaceAt(ray, closest);
            bool fromOutside = dot(ray.dir, surf.normal) < 0.0;
            vec3 facing = surf.normal;
            if (!fromOutside) {
                facing = -surf.normal;
            }
            pixel = pixel + weight * blinnPhong(surf.point, facing, -ray.dir, surf.material);
            bool canBounce = depth < uMaxDepth;
            if (surf.material.type != MAT_PLASTIC && canBounce) {
                vec3 keep;
                if (surf.material.type == MAT_GLASS) {
                    vec4 result = refractGlass(ray.dir, facing, fromOutside, surf.material.ior);
                    bool refracts = result.x != 0.0 || result.y != 0.0 || result.z != 0.0;
                    if (refracts) {
                        Ray inside = Ray(offsetRayOrigin(surf.point, -facing), result.xyz);
                        pushRay(inside, weight * (1.0 - result.w), depth + 1);
                    }
                    keep = vec3(result.w);
                } else {
                    keep = reflectanceOf(surf.material, -dot(ray.dir, facing));
                }
                Ray bounced = Ray(offsetRayOrigin(surf.point, facing), reflect(ray.dir, facing));
                ray = bounced;
                weight = weight * keep;
                depth = depth + 1;
                continues = true;
            }
        }
        if (continues == false) {
            if (waitingCount == 0) {
                break;
            }
            waitingCount = waitingCount - 1;
            ray = waitingRays[waitingCount];
            weight = waitingWeights[waitingCount];
            depth = waitingDepths[waitingCount];
        }
    }
    return pixel;
}
