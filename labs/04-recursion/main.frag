// Stage 04 - recursion turned into a loop. Every pixel's primary ray is
// handed to trace(), which follows reflections and refractions with an
// explicit stack, adding each hit's Blinn-Phong colour (with shadows).
#include "ray.glsl"
#include "scene_spheres.glsl"
#include "scene_materials.glsl"
#include "scene_lights.glsl"
#include "lab_todo.glsl"
#include "intersect_sphere.glsl"
#include "find_closest.glsl"
#include "surface.glsl"
#include "surface_at.glsl"
#include "sky.glsl"
#include "blinn_phong.glsl"
#include "fresnel.glsl"
#include "trace.glsl"

in vec3 vsRay;
uniform vec3 uEye;
layout(location = 0) out vec4 fragColor;

void main()
{
    fragColor = vec4(labOverlay(trace(Ray(uEye, normalize(vsRay)))), 1.0);
}
