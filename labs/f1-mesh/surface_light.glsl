// How much light a point of the skin sends toward the eye: the light that
// reaches every point (ambient) plus Lambert's diffuse term, which is
// brightest where the surface faces the light and zero where it faces away.
#include "lab_todo.glsl"
#include "fur_uniforms.glsl"

vec3 surfaceLight(vec3 albedo, vec3 normal, vec3 toLight)
{
    // TODO(f1.c): return albedo * (uAmbient + uLightColor * max(n . l, 0)).
    // NORMAL arrives interpolated between vertices, so it is no longer unit
    // length: normalise it first.
    // Checked by: raylab check --stage f1 (function surfaceLight; all views).
    labTodo();
    return albedo;
}
