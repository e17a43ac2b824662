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
    vec4 world = toWorld(aPosition);
    gl_Position = toClip(world);
    vWorldPos = world.xyz;
    vNormal = normalMatrix(uModel) * aNormal;
    vUv = aUv;
    vLabTodo = gLabTodoReached ? 1 : 0;
}
