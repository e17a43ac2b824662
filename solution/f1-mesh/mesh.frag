// Stage f1, per pixel: the lit colour of the mesh. The framework turns on
// the depth test (the nearest surface wins) and back-face culling
// (triangles facing away are skipped); the guide explains both.
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "surface_light.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
flat in int vLabTodo;

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 albedo = texture(uColorMap, vUv).rgb;
    vec3 color = surfaceLight(albedo, vNormal, uLightDir);
    labTodoIf(vLabTodo != 0);
    fragColor = vec4(labOverlay(color), 1.0);
}
