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

// TODO(f3.b): a fin on every silhouette edge.
// The fin of edge B-C (vertices 1 and 2; 0 and 3 are A and D),
// only when the edge is on the silhouette seen from uEye (isSilhouette):
// one quad, emitted as a triangle strip of 4 vertices (guide, sections 2, 5),
// standing on the edge: its root edge is B-C, its top edge B and C moved
// along their own vertex normals (vNormal[1], vNormal[2]) by uFurLength,
// so that neighbouring fins meet at the top as they do at the root. Each
// vertex gets gl_Position (toClip) and the outputs above:
//  - gFinUv: u along the edge in fur lengths (0 at B, |C - B| / uFurLength
//    at C), v 0 at the root and 1 at the top;
//  - gSkinUv and gNormal: those of the edge vertex it stands on;
//  - gFade: finFade(b, c, vNormal[1], vNormal[2]), the same for all four;
//  - gLabTodo: 1 when gLabTodoReached or its edge vertex's vLabTodo is set.
// Checked by: raylab check --stage f3 (fin count; views coarse, grazing; every view with fins).
void emitCorner(vec3 p, vec2 finUv, int i, float fade)
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
    vec3 a = vWorldPos[0];
    vec3 b = vWorldPos[1];
    vec3 c = vWorldPos[2];
    vec3 d = vWorldPos[3];
    if (!isSilhouette(uEye, a, b, c, d))
        return;

    vec3 topB = b + uFurLength * vNormal[1];
    vec3 topC = c + uFurLength * vNormal[2];
    float uC = length(c - b) / uFurLength;
    float fade = finFade(b, c, vNormal[1], vNormal[2]);

    emitCorner(b, vec2(0.0, 0.0), 1, fade);
    emitCorner(c, vec2(uC, 0.0), 2, fade);
    emitCorner(topB, vec2(0.0, 1.0), 1, fade);
    emitCorner(topC, vec2(uC, 1.0), 2, fade);
    EndPrimitive();
}
