// Stage f2, per pixel of one shell: a hair of the pattern or a gap.
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "shell_alpha.glsl"
#include "shell_shadow.glsl"
#include "surface_light.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
in float vLayer;
flat in int vLabTodo;

layout(location = 0) out vec4 fragColor;

void main()
{
    float pattern = texture(uPattern, vUv * uPatternScale).r;
    float alpha = shellAlpha(pattern, vLayer);
    // No hair here: leave the pixel to the shells below (and write nothing).
    if (alpha < 0.001) discard;
    vec3 albedo = texture(uColorMap, vUv).rgb * shellShadow(vLayer, uShadowIntensity);
    vec3 color = surfaceLight(albedo, vNormal, uLightDir);
    labTodoIf(vLabTodo != 0);
    fragColor = vec4(labOverlay(color), alpha);
}
