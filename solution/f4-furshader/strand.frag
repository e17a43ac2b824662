// Stage f4, per pixel of a strand: Kajiya-Kay lighting along the strand,
// dimmed where the skin below faces away from the light.
#include "fur_uniforms.glsl"
#include "kajiya_kay.glsl"
#include "lab_todo.glsl"
#include "shell_shadow.glsl"

in vec3 gWorldPos;
in vec3 gTangent;
in vec3 gNormal;
in vec2 gUv;
in float gS;
flat in int gLabTodo;

layout(location = 0) out vec4 fragColor;

const float kShininess = 40.0;
const float kSpecular = 0.35;

void main()
{
    vec3 toEye = normalize(uEye - gWorldPos);
    //@open
    //@ // TODO(f4.c): the strand lit along its direction.
    //@ // The strand's light (diffuse, specular) from kajiyaKay with
    //@ // shininess kShininess: a strand has no normal, only a direction.
    //@ // Checked by: raylab check --stage f4 (view "fur-shader-shaggy").
    //@ labTodo();
    //@ vec2 light = vec2(1.0, 0.0);
    //@guided
    // TODO(f4.c): light the strand with kajiyaKay(): a strand is a thin
    // cylinder, so its direction is the strand's tangent (gTangent, not yet
    // unit length), not the skin's normal.
    // Checked by: raylab check --stage f4 (view "fur-shader-shaggy": long
    // drooping strands, whose tangents are far from the skin's normal).
    //@solution
    vec2 light = kajiyaKay(normalize(gTangent), uLightDir, toEye, kShininess);
    //@stub
    //@ labTodo();
    //@ vec2 light = vec2(1.0, 0.0);
    //@end
    //@end-open
    // The hairs on the far side of the body are in its shadow.
    float skin = clamp(dot(gNormal, uLightDir) * 0.5 + 0.5, 0.0, 1.0);
    vec3 albedo = texture(uColorMap, gUv).rgb * shellShadow(gS, uShadowIntensity);
    vec3 color = albedo * (uAmbient + uLightColor * light.x * skin) +
                 uLightColor * (kSpecular * light.y * skin);
    labTodoIf(gLabTodo != 0);
    fragColor = vec4(labOverlay(color), 1.0);
}
