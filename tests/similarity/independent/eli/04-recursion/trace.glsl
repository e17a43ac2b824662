// The ray tracer: every ray a pixel's primary ray leads to, by reflection
// and refraction, up to a depth limit. GLSL has no recursive calls.
#include "ray_offset.glsl"

uniform int uMaxDepth;  // rays per path, 1..MAX_DEPTH (arrow keys; MAX_DEPTH = 8 is defined by the framework)

/*
 * Eli's ray tracer.
 *
 * Work list: three parallel arrays used as a LIFO stack of pending rays,
 * each with the colour weight it carries to the pixel and its depth along
 * its path. Every loop pass pops one ray, adds weight * (local colour) and
 * pushes whatever rays that surface spawns. Pushing both children of a glass
 * hit and popping one straight away never holds more than MAX_DEPTH entries:
 * the rays below the children have distinct depths smaller than theirs.
 */
Ray  eliPendingRay[MAX_DEPTH];
vec3 eliPendingWeight[MAX_DEPTH];
int  eliPendingDepth[MAX_DEPTH];
int  eliPendingCount = 0;

void eliPush(Ray r, vec3 weight, int depth)
{
    if (eliPendingCount >= MAX_DEPTH) {
        return;                            /* full: should never happen, but never overrun */
    }
    eliPendingRay[eliPendingCount] = r;
    eliPendingWeight[eliPendingCount] = weight;
    eliPendingDepth[eliPendingCount] = depth;
    eliPendingCount += 1;
}

/* How much of a reflected ray's colour comes back from a mirror or a metal. */
vec3 eliReflectance(Material mat, vec3 incoming, vec3 facingNormal)
{
    if (mat.type == MAT_METAL) {
        float cosIncident = clamp(dot(-incoming, facingNormal), 0.0, 1.0);
        return fresnelConductor(cosIncident, mat.n, mat.k);
    }
    return mat.specular;                   /* mirror: the same at every angle */
}

vec3 trace(Ray primary)
{
    vec3 pixelColor = vec3(0.0);
    eliPendingCount = 0;
    eliPush(primary, vec3(1.0), 1);

    int raysFollowed = 0;
    while (eliPendingCount > 0 && raysFollowed < MAX_RAYS) {
        raysFollowed += 1;

        /* pop */
        eliPendingCount -= 1;
        Ray ray = eliPendingRay[eliPendingCount];
        vec3 weight = eliPendingWeight[eliPendingCount];
        int depth = eliPendingDepth[eliPendingCount];

        Hit nearest;
        bool somethingHit = findClosest(ray, nearest);
        if (somethingHit) {
            Surface surf = surfaceAt(ray, nearest);
            Material mat = surf.material;
            bool fromOutside = dot(surf.normal, ray.dir) < 0.0;
            vec3 towardRay = surf.normal;
            if (!fromOutside) {
                towardRay = -surf.normal;      /* we are inside the object */
            }

            pixelColor += weight * blinnPhong(surf.point, towardRay, -ray.dir, mat);

            bool spawns = (mat.type != MAT_PLASTIC) && (depth < uMaxDepth);
            if (spawns) {
                int childDepth = depth + 1;
                vec3 mirrorDir = reflect(ray.dir, towardRay);
                Ray bounced = Ray(offsetRayOrigin(surf.point, towardRay), mirrorDir);

                if (mat.type == MAT_GLASS) {
                    vec4 dirAndF = refractGlass(ray.dir, towardRay, fromOutside, mat.ior);
                    float reflectedShare = dirAndF.w;
                    eliPush(bounced, weight * reflectedShare, childDepth);
                    if (reflectedShare < 1.0) {
                        /* the transmitted ray starts on the far side of the surface */
                        Ray transmitted = Ray(offsetRayOrigin(surf.point, -towardRay), dirAndF.xyz);
                        eliPush(transmitted, weight * (1.0 - reflectedShare), childDepth);
                    }
                } else {
                    eliPush(bounced, weight * eliReflectance(mat, ray.dir, towardRay), childDepth);
                }
            }
        } else {
            pixelColor += weight * skyColor(ray.dir);
        }
    }
    return pixelColor;
}
