// Stage f3, per pixel of a fin: the fin texture's strands, coloured like the
// coat and darkened toward the root like the shells.
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "shell_shadow.glsl"
#include "surface_light.glsl"

in vec2 gFinUv;
in vec2 gSkinUv;
in vec3 gNormal;
in float gFade;
flat in int gLabTodo;

layout(location = 0) out vec4 fragColor;

void main()
{
    float alpha = texture(uFinMap, gFinUv).a * gFade;
    if (alpha < 0.001) discard;
    vec3 albedo = texture(uColorMap, gSkinUv).rgb * shellShadow(gFinUv.y, uShadowIntensity);
    vec3 color = surfaceLight(albedo, gNormal, uLightDir);
    labTodoIf(gLabTodo != 0);
    fragColor = vec4(labOverlay(color), alpha);
}
