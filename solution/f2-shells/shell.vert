// Stage f2, per vertex of one shell: the vertex pushed off the skin along
// its normal, by its layer's share of the fur length.
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "normal_matrix.glsl"
#include "transform.glsl"
#include "shell_layer.glsl"
#include "shell_offset.glsl"

layout(location = 0) in vec3 aPosition;  // object space
layout(location = 1) in vec3 aNormal;    // object space, unit length
layout(location = 2) in vec2 aUv;

out vec3 vWorldPos;
out vec3 vNormal;  // world space
out vec2 vUv;
out float vLayer;  // 0 at the skin, 1 at the tips
flat out int vLabTodo;

void main()
{
    //@open
    //@ // TODO(f2.e): the vertex shader of a shell.
    //@ // The vertex of shell number uShellIndex of uShellCount: its
    //@ // layer (shellLayer), the vertex moved off the skin by shellOffset along
    //@ // its world-space normal - in world space, so that the fur keeps its
    //@ // length however the model is scaled - and the outputs above (vNormal
    //@ // unit length).
    //@ // Checked by: raylab check --stage f2 (views rim, squashed, torus; all views).
    //@ labTodo();
    //@ gl_Position = toClip(toWorld(aPosition));
    //@ vWorldPos = toWorld(aPosition).xyz;
    //@ vNormal = vec3(0.0, 0.0, 1.0);
    //@ vUv = aUv;
    //@ vLayer = 0.0;
    //@ vLabTodo = gLabTodoReached ? 1 : 0;
    //@guided
    float layer = shellLayer(uShellIndex, uShellCount);
    // The offset is taken in world space, so that the fur keeps its length
    // however the model is scaled.
    vec3 normal = normalize(normalMatrix(uModel) * aNormal);
    vec4 world = toWorld(aPosition);
    world.xyz += shellOffset(normal, layer, uFurLength);
    vWorldPos = world.xyz;
    gl_Position = toClip(world);
    vNormal = normal;
    vUv = aUv;
    vLayer = layer;
    vLabTodo = gLabTodoReached ? 1 : 0;
    //@end-open
}
