// Stage 05 - more kinds of object: infinite planes, discs, triangles (a
// mirror of two, a glass cube of twelve) and a torus. The tracer of lab 04
// is unchanged: findClosest() and surfaceAt() learn the new kinds.
#include "ray.glsl"
#include "scene_spheres.glsl"
#include "scene_materials.glsl"
#include "scene_objects.glsl"
#include "scene_lights.glsl"
#include "lab_todo.glsl"
#include "intersect_sphere.glsl"
#include "intersect_plane.glsl"
#include "intersect_disc.glsl"
#include "intersect_triangle.glsl"
#include "intersect_torus.glsl"
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
