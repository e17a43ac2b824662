// Stage f1, per vertex: where the vertex lands on the screen, and what the
// fragment shader needs (world position, world normal, texture coordinate).
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "normal_matrix.glsl"
#include "transform.glsl"

layout(location = 0) in vec3 aPosition;  // object space
layout(location = 1) in vec3 aNormal;    // object space, unit length
layout(location = 2) in vec2 aUv;

out vec3 vWorldPos;
out vec3 vNormal;  // world space
out vec2 vUv;
flat out int vLabTodo;  // 1 when this vertex went through an unfinished TODO

void main()
{
    //@open
    //@ // TODO(f1.d): the vertex shader of the lit mesh.
    //@ // The vertex on the screen (gl_Position, through toWorld and
    //@ // toClip) and what the fragment shader needs: its world position, its
    //@ // world-space normal (normalMatrix) and its texture coordinate, as the
    //@ // outputs above say; vLabTodo as below.
    //@ // Checked by: raylab check --stage f1 (all views).
    //@ labTodo();
    //@ gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    //@ vWorldPos = vec3(0.0);
    //@ vNormal = vec3(0.0, 0.0, 1.0);
    //@ vUv = vec2(0.0);
    //@ vLabTodo = gLabTodoReached ? 1 : 0;
    //@guided
    vec4 world = toWorld(aPosition);
    gl_Position = toClip(world);
    vWorldPos = world.xyz;
    vNormal = normalMatrix(uModel) * aNormal;
    vUv = aUv;
    vLabTodo = gLabTodoReached ? 1 : 0;
    //@end-open
}
