// Variant of solution/08-full/light_visibility.glsl, used instead of it when
// RAYLAB_OLD_PATH is defined: a shadow ray even toward a light behind the
// surface, kept so that `raylab bench` can show what skipping it saves (its
// "old-path" row). Not part of any lab: students never see this file.
// Does light `light` reach `point`? Lab 03's answer, with one change for
// speed: the shadow ray asks findBlocker (find_closest.glsl), which may stop
// at the first object between the point and the light, instead of searching
// for the nearest one. (Provided.)
//   point  - a surface point (a hit found by findClosest)
//   normal - unit surface normal at the point (facing the eye)
// uShadows == 0 (key 1 in the window) turns shadows off: every light is visible.
#include "ray_offset.glsl"

uniform int uShadows;

bool lightVisible(vec3 point, vec3 normal, int light)
{
    if (uShadows == 0) return true;
    vec3 toLight = uLightPositions[light] - point;
    float distanceToLight = length(toLight);
    vec3 dir = toLight / distanceToLight;
    vec3 side = dot(normal, dir) >= 0.0 ? normal : -normal;  // the side the light is on
    return !findBlocker(Ray(offsetRayOrigin(point, side), dir), distanceToLight);
}
