//@open
//@ // Does light `light` reach `point`? Lab 03's question, for the full demo.
//@guided
// Does light `light` reach `point`? Lab 03's answer, with two changes for
// speed: the shadow ray asks findBlocker (find_closest.glsl), which may stop
// at the first object between the point and the light, instead of searching
// for the nearest one; and a light behind the surface gets no shadow ray at
// all. (Provided.)
//@end-open
//   point  - a surface point (a hit found by findClosest)
//   normal - unit surface normal at the point (facing the eye)
// uShadows == 0 (key 1 in the window) turns shadows off: every light is visible.
#include "ray_offset.glsl"

uniform int uShadows;

bool lightVisible(vec3 point, vec3 normal, int light)
{
    //@open
    //@ // TODO(08.c): lab 03's lightVisible, faster.
    //@ // The same contract as lab 03's (true when uShadows == 0; the shadow ray
    //@ // starts at offsetRayOrigin on the light's side; only objects nearer
    //@ // than the light block it), with two changes for speed: ask
    //@ // findBlocker(ray, maxT) (find_closest.glsl), which may stop at the
    //@ // first object nearer than maxT (the light's distance), instead of
    //@ // findClosest; and send no shadow ray to a light behind the surface (it
    //@ // adds nothing to blinnPhong).
    //@ // Checked by: raylab check --stage 08 (function lightVisibleFast; views lite-front, pro-front).
    //@ labTodo();
    //@ return true;
    //@guided
    if (uShadows == 0) return true;
    vec3 toLight = uLightPositions[light] - point;
    float distanceToLight = length(toLight);
    vec3 dir = toLight / distanceToLight;
    // A light behind the surface adds nothing (blinn_phong.glsl: lambert 0,
    // no specular), so it needs no shadow ray: a third of pro's.
    if (dot(normal, dir) <= 0.0) return false;
    // So the light is on the normal's side: the ray leaves from there.
    return !findBlocker(Ray(offsetRayOrigin(point, normal), dir), distanceToLight);
    //@end-open
}
