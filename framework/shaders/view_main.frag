// The debug views (`raylab render --view depth|normal|id`, `raylab rays`):
// the stage's own shader files, with a main() that writes a number about
// the primary ray instead of a colour. The framework builds this file in
// place of the stage's main.frag, with RAYLAB_VIEW set to one of the values
// below and RAYLAB_VIEW_SURFACE_AT defined from stage 04 on (surfaceAt()
// exists there). (Students need not change this file.)
//
// Output (a float render target), alpha 1 where the primary ray hit
// something and 0 where it missed:
//   depth:  r = hit distance t along the primary ray (0 for a miss), g = object id
//   normal: rgb = unit outward normal at the hit (0 for a miss)
//   id:     r = the object id, kind * 1048576 + index (-1 for a miss)
//   rays:   rgb = the primary ray's direction, normalize(vsRay) (alpha 1)
#define RAYLAB_VIEW_DEPTH 1
#define RAYLAB_VIEW_NORMAL 2
#define RAYLAB_VIEW_ID 3
#define RAYLAB_VIEW_RAYS 4

// The stage's main() is renamed: its declarations (vsRay, uEye, fragColor)
// and every file it includes stay as they are.
#define main stageColorMain
#include "main.frag"
#undef main

void main()
{
    Ray ray = Ray(uEye, normalize(vsRay));  // exactly as the stages' main.frag
#if RAYLAB_VIEW == RAYLAB_VIEW_RAYS
    fragColor = vec4(ray.dir, 1.0);
#else
    Hit hit;
    if (!findClosest(ray, hit)) {
#if RAYLAB_VIEW == RAYLAB_VIEW_ID
        fragColor = vec4(-1.0, 0.0, 0.0, 0.0);
#else
        fragColor = vec4(0.0);
#endif
        return;
    }
#if RAYLAB_VIEW == RAYLAB_VIEW_DEPTH
    fragColor = vec4(hit.t, float(hit.id), 0.0, 1.0);  // g: the id, so depth errors can be compared per object
#elif RAYLAB_VIEW == RAYLAB_VIEW_NORMAL
#ifdef RAYLAB_VIEW_SURFACE_AT
    vec3 normal = surfaceAt(ray, hit).normal;
#else
    vec3 normal = normalize(ray.origin + hit.t * ray.dir - uSpheres[hit.id].xyz);  // stages 01-03: spheres only
#endif
    fragColor = vec4(normal, 1.0);
#else
    fragColor = vec4(float(hit.id), 0.0, 0.0, 1.0);
#endif
#endif
}
