// Stage 06 - textures: pictures wrapped around spheres (earth, moon, sun)
// and tiled on planes, a sky box far away, and a glow around the sun.
#include "ray.glsl"
#include "scene_spheres.glsl"
#include "scene_materials.glsl"
#include "scene_objects.glsl"
#include "scene_lights.glsl"
#include "scene_textures.glsl"
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
#include "glow.glsl"

in vec3 vsRay;
uniform vec3 uEye;
layout(location = 0) out vec4 fragColor;

void main()
{
    Ray primary = Ray(uEye, normalize(vsRay));
    vec3 color = trace(primary);
    if (uGlow != 0) color += sunGlow(primary);
    fragColor = vec4(labOverlay(color), 1.0);
}
