// How much light a point of the skin sends toward the eye: the light that
// reaches every point (ambient) plus Lambert's diffuse term, which is
// brightest where the surface faces the light and zero where it faces away.
#include "lab_todo.glsl"
#include "fur_uniforms.glsl"

vec3 surfaceLight(vec3 albedo, vec3 normal, vec3 toLight)
{
    //@open
    //@ // TODO(f1.c): ambient light plus Lambert.
    //@ // The colour the point sends toward the eye: ALBEDO lit by the
    //@ // ambient light uAmbient plus Lambert's diffuse term of the light
    //@ // uLightColor coming from the unit direction TOLIGHT (toward the light).
    //@ // NORMAL is the interpolated surface normal: not unit length any more.
    //@ // Checked by: raylab check --stage f1 (function surfaceLight; all views).
    //@ labTodo();
    //@ return albedo;
    //@guided
    // TODO(f1.c): return albedo * (uAmbient + uLightColor * max(n . l, 0)).
    // NORMAL arrives interpolated between vertices, so it is no longer unit
    // length: normalise it first.
    // Checked by: raylab check --stage f1 (function surfaceLight; all views).
    //@solution
    vec3 n = normalize(normal);
    return albedo * (uAmbient + uLightColor * max(dot(n, toLight), 0.0));
    //@stub
    //@ labTodo();
    //@ return albedo;
    //@end
    //@end-open
}
