// Stage 08 - the full tracer of the demo: every kind of object, textures,
// normal maps, sky box, glow, shadows, reflection and refraction to depth 8,
// and the colour modes.
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
#include "color_mode.glsl"

in vec3 vsRay;
uniform vec3 uEye;
out vec4 fragColor;

void main()
{
    Ray primary = Ray(uEye, normalize(vsRay));
    vec3 color = trace(primary);
    if (uGlow != 0) color += sunGlow(primary);
    fragColor = vec4(labOverlay(applyColorMode(color)), 1.0);
}
