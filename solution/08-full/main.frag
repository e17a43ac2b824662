// Stage 08 - the full tracer of the demo: every kind of object, textures,
// normal maps, sky box, glow, shadows, reflection and refraction to depth 8,
// and the colour modes. No NaN or Inf reaches the framebuffer (see main()).
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
layout(location = 0) out vec4 fragColor;

// What a pixel shows when its colour is NaN or infinite (a 0/0 or an
// overflow somewhere in the tracer): magenta, the colour `raylab check`,
// grading and `raylab render --out *.pfm` give NaN pixels when they read a
// float frame. Visible rather than black on purpose - black would hide the
// bug as a dark speck, and an 8-bit framebuffer would turn the NaN into an
// undefined value. (tests/numerics/degenerate_test.cpp provokes it.)
const vec3 NON_FINITE_COLOR = vec3(1.0, 0.0, 1.0);

// True when no channel is NaN or +-Inf: their exponent bits are all ones.
// Tested on the bits, because a compiler may assume that x != x is false.
bool isFiniteColor(vec3 c)
{
    uvec3 exponent = floatBitsToUint(c) & uvec3(0x7f800000u);
    return all(notEqual(exponent, uvec3(0x7f800000u)));
}

void main()
{
    Ray primary = Ray(uEye, normalize(vsRay));
    vec3 color = trace(primary);
    if (uGlow != 0) color += sunGlow(primary);
    color = labOverlay(applyColorMode(color));
    fragColor = vec4(isFiniteColor(color) ? color : NON_FINITE_COLOR, 1.0);
}
