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
    //@open
    //@ // TODO(03.a): whether the light reaches the point.
    //@ // Return whether light number `light` (at uLightPositions[light])
    //@ // reaches `point`: false when findClosest finds an object between the point
    //@ // and the light, true otherwise (and always true when uShadows == 0).
    //@ //  - The shadow ray starts just off the surface, with offsetRayOrigin, on
    //@ //    the side it leaves toward: the light's side (guide, section 2).
    //@ //  - An object beyond the light casts no shadow on the point.
    //@ // Checked by: raylab check --stage 03 (function lightVisible; views front, grazing, beyond-light, far-from-origin).
    //@ labTodo();
    //@ return true;
    //@guided
    if (uShadows == 0) return true;
    vec3 toLight = uLightPositions[light] - point;
    float distanceToLight = length(toLight);
    vec3 dir = toLight / distanceToLight;

    // TODO(03.a): start the shadow ray just off the surface, on the side it
    // leaves from - the side the light is on: offsetRayOrigin(point, side),
    // with side = normal if the light is in front of the surface, -normal if
    // behind it.
    // Checked by: raylab check --stage 03 (function lightVisible, views front, grazing, far-from-origin).
    //@solution
    vec3 side = dot(normal, dir) >= 0.0 ? normal : -normal;
    Ray shadowRay = Ray(offsetRayOrigin(point, side), dir);
    //@stub
    //@ labTodo();
    //@ Ray shadowRay = Ray(point, dir);
    //@end

    // TODO(03.b): the light is blocked when findClosest finds an object
    // between the start of the shadow ray and the light - not beyond it.
    // Checked by: raylab check --stage 03 (function lightVisible, views front, beyond-light).
    //@solution
    Hit blocker;
    return !(findClosest(shadowRay, blocker) && blocker.t < distanceToLight);
    //@stub
    //@ labTodo();
    //@ return true;
    //@end
    //@end-open
}
