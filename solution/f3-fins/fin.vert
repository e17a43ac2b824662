// Stage f3, per vertex of the fin (and, in f4, strand) program: no
// projection yet - the geometry shader builds the fins in world space and
// projects them itself.
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "normal_matrix.glsl"
#include "transform.glsl"

layout(location = 0) in vec3 aPosition;  // object space
layout(location = 1) in vec3 aNormal;    // object space, unit length
layout(location = 2) in vec2 aUv;

out vec3 vWorldPos;
out vec3 vNormal;  // world space, unit length
out vec2 vUv;
flat out int vLabTodo;

void main()
{
    vWorldPos = toWorld(aPosition).xyz;
    vNormal = normalize(normalMatrix(uModel) * aNormal);
    vUv = aUv;
    vLabTodo = gLabTodoReached ? 1 : 0;
}
