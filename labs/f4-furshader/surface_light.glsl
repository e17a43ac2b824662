// How much light a point of the skin sends toward the eye: the light that
// reaches every point (ambient) plus Lambert's diffuse term, which is
// brightest where the surface faces the light and zero where it faces away.
#include "lab_todo.glsl"
#include "fur_uniforms.glsl"

vec3 surfaceLight(vec3 albedo, vec3 normal, vec3 toLight)
{
    vec3 n = normalize(normal);
    return albedo * (uAmbient + uLightColor * max(dot(n, toLight), 0.0));
}
