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
    //@open
    //@ // TODO(f2.f): the fragment shader of a shell.
    //@ // The colour and opacity of this pixel of a shell: the fur
    //@ // pattern uPattern (tiled uPatternScale times over the skin's texture
    //@ // coordinates) gives shellAlpha; where that is below 0.001 nothing is
    //@ // drawn (discard), so the shells below show through. The colour is the
    //@ // colour map's, darkened by shellShadow (uShadowIntensity) and lit by
    //@ // surfaceLight (uLightDir). Write it through labOverlay, after
    //@ // labTodoIf(vLabTodo != 0): the marks of unfinished TODOs.
    //@ // Checked by: raylab check --stage f2 (views front, close; all views).
    //@ labTodo();
    //@ labTodoIf(true);
    //@ fragColor = vec4(labOverlay(texture(uColorMap, vUv).rgb), 1.0);
    //@guided
    float pattern = texture(uPattern, vUv * uPatternScale).r;
    float alpha = shellAlpha(pattern, vLayer);
    // No hair here: leave the pixel to the shells below (and write nothing).
    if (alpha < 0.001) discard;
    vec3 albedo = texture(uColorMap, vUv).rgb * shellShadow(vLayer, uShadowIntensity);
    vec3 color = surfaceLight(albedo, vNormal, uLightDir);
    labTodoIf(vLabTodo != 0);
    fragColor = vec4(labOverlay(color), alpha);
    //@end-open
}
