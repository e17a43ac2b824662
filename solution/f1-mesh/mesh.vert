// Stage f1, per vertex: where the vertex lands on the screen, and what the
// fragment shader needs (world position, world normal, texture coordinate).
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "normal_matrix.glsl"

layout(location = 0) in vec3 aPosition;  // object space
layout(location = 1) in vec3 aNormal;    // object space, unit length
layout(location = 2) in vec2 aUv;

out vec3 vWorldPos;
out vec3 vNormal;  // world space
out vec2 vUv;
flat out int vLabTodo;  // 1 when this vertex went through an unfinished TODO

void main()
{
    // TODO(f1.a): place the vertex. uModel takes a point from object space
    // to world space, uView from world space to the camera's, uProjection
    // from the camera's to clip space. Set world (the point in world space)
    // and gl_Position (clip space); a point is vec4(p, 1.0).
    // Checked by: raylab check --stage f1 (all views).
    //@solution
    vec4 world = uModel * vec4(aPosition, 1.0);
    gl_Position = uProjection * uView * world;
    //@stub
    //@ labTodo();
    //@ vec4 world = vec4(aPosition, 1.0);
    //@ gl_Position = vec4(0.5 * aPosition.xy, 0.0, 1.0);
    //@end
    vWorldPos = world.xyz;
    vNormal = normalMatrix(uModel) * aNormal;
    vUv = aUv;
    vLabTodo = gLabTodoReached ? 1 : 0;
}
