// Does light `light` reach `point`, or is something in between?
//   point  - a surface point (a hit found by findClosest)
//   normal - unit surface normal at the point (facing the eye)
// uShadows == 0 (key 1 in the window) turns shadows off: every light is visible.
#include "ray_offset.glsl"

uniform int uShadows;

// Where a shadow ray starts: vec3 offsetRayOrigin(vec3 point, vec3 side)
// (provided by the framework, in framework/shaders/ray_offset.glsl) returns
// the point moved just off the surface, to the side `side` (a unit normal
// or its opposite).
// A hit point computed in floating point lies a tiny bit above or below the
// true surface; started exactly there, the ray could hit its own surface
// ("shadow acne"). How far is "just off" grows with the size of the
// coordinates: a fixed distance fails in big scenes (guide, section 2).

bool lightVisible(vec3 point, vec3 normal, int light)
{
    if (uShadows == 0) return true;
    vec3 toLight = uLightPositions[light] - point;
    float distanceToLight = length(toLight);
    vec3 dir = toLight / distanceToLight;

    vec3 side = dot(normal, dir) >= 0.0 ? normal : -normal;
    Ray shadowRay = Ray(offsetRayOrigin(point, side), dir);

    Hit blocker;
    return !(findClosest(shadowRay, blocker) && blocker.t < distanceToLight);
}
