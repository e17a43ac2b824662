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

/*
 * Eli's fin builder.
 *
 * eliEmitCorner writes ONE vertex of the fin and emits it. `endIndex` is the
 * input vertex the corner belongs to (1 = B, 2 = C), `height` is 0 at the
 * root and 1 at the tip, and the top corner is pushed out along that
 * vertex's own normal so neighbouring fins share their top points.
 */
void eliEmitCorner(int endIndex, float height, float edgeLengthInFur, float fadeForFin)
{
    vec3 rootPoint = vWorldPos[endIndex];
    vec3 cornerPoint = rootPoint + vNormal[endIndex] * (height * uFurLength);
    float alongEdge = (endIndex == 2) ? edgeLengthInFur : 0.0;

    gFinUv = vec2(alongEdge, height);
    gSkinUv = vUv[endIndex];
    gNormal = vNormal[endIndex];
    gFade = fadeForFin;
    bool todoSeen = gLabTodoReached || (vLabTodo[endIndex] != 0);
    gLabTodo = todoSeen ? 1 : 0;
    gl_Position = toClip(vec4(cornerPoint, 1.0));
    EmitVertex();
}

void main()
{
    bool onOutline = isSilhouette(uEye, vWorldPos[0], vWorldPos[1], vWorldPos[2], vWorldPos[3]);
    if (onOutline) {
        float edgeLengthInFur = distance(vWorldPos[1], vWorldPos[2]) / uFurLength;
        float fadeForFin = finFade(vWorldPos[1], vWorldPos[2], vNormal[1], vNormal[2]);

        /* Strip order B, C, topB, topC: corner k sits on vertex 1 + (k % 2)
         * at height k / 2, which zig-zags across the quad. */
        for (int k = 0; k < 4; ++k) {
            eliEmitCorner(1 + (k % 2), float(k / 2), edgeLengthInFur, fadeForFin);
        }
        EndPrimitive();
    }
}
