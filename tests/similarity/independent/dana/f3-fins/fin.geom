// Stage f3: a fin on every silhouette edge. The framework draws the mesh's
// edges as GL_LINES_ADJACENCY: each invocation gets four vertices, the edge
// B-C (1 and 2) and the far corners A (0) and D (3) of its two triangles.
// For a silhouette edge it emits one quad standing on the edge - the fur
// seen from the side, where the shells show gaps between them.
layout(lines_adjacency) in;
layout(triangle_strip, max_vertices = 4) out;

#include "fur_uniforms.glsl"
#include "transform.glsl"
#include "lab_todo.glsl"
#include "silhouette.glsl"

in vec3 vWorldPos[];
in vec3 vNormal[];
in vec2 vUv[];
flat in int vLabTodo[];

out vec2 gFinUv;   // u along the edge, v from the root (0) to the tip (1)
out vec2 gSkinUv;  // the mesh's texture coordinate (for the colour)
out vec3 gNormal;  // world space
out float gFade;   // 1 where the eye grazes the surface, less where it looks down on it
flat out int gLabTodo;

// How much of a fin shows: 1 where the eye grazes the surface, less where
// it looks down on it (a fin seen face-on looks like a flat card), from the
// edge B-C and its vertex normals. (Provided.)
float finFade(vec3 b, vec3 c, vec3 normalB, vec3 normalC)
{
    vec3 n = normalB + normalC;
    vec3 toEye = normalize(uEye - 0.5 * (b + c));
    return dot(n, n) > 1e-12 ? 1.0 - abs(dot(toEye, normalize(n))) : 1.0;
}

// dana: one corner of the fin. Every output is written again before each
// EmitVertex (they are undefined after it). `i` is the edge vertex (1 = B,
// 2 = C) the corner stands on; its skin uv, normal and todo flag are used.
void corner(vec3 p, int i, vec2 finUv, float fade)
{
    gl_Position = toClip(vec4(p, 1.0));
    gFinUv = finUv;
    gSkinUv = vUv[i];
    gNormal = vNormal[i];
    gFade = fade;
    gLabTodo = (gLabTodoReached || vLabTodo[i] != 0) ? 1 : 0;
    EmitVertex();
}

void main()
{
    vec3 B = vWorldPos[1];
    vec3 C = vWorldPos[2];
    if (!isSilhouette(uEye, vWorldPos[0], B, C, vWorldPos[3])) return;   // no fin

    float fade = finFade(B, C, vNormal[1], vNormal[2]);
    float uC = length(C - B) / uFurLength;   // one texture repeat per fur length

    // zig-zag strip: B, C, topB, topC -> triangles (B,C,topB), (C,topB,topC)
    corner(B, 1, vec2(0.0, 0.0), fade);
    corner(C, 2, vec2(uC, 0.0), fade);
    corner(B + uFurLength * vNormal[1], 1, vec2(0.0, 1.0), fade);
    corner(C + uFurLength * vNormal[2], 2, vec2(uC, 1.0), fade);
    EndPrimitive();
}
