// The web build's fins (stage f3): WebGL 2 has no geometry shaders, so the
// fins are instanced quads, one instance per mesh edge, and this vertex
// shader does what fin.geom does natively: the silhouette test
// (silhouette.glsl, the student's) and the quad standing on the edge. It
// feeds fin.frag unchanged. Its top edge is built as the solution of
// TODO(f3.b) builds it: that TODO lives in fin.geom, which only the native
// build compiles. (Students need not change this file.)
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "normal_matrix.glsl"
#include "silhouette.glsl"

// Per instance (one edge B-C with its far corners A and D), object space.
layout(location = 3) in vec3 aEdgeA;
layout(location = 4) in vec3 aEdgeB;
layout(location = 5) in vec3 aEdgeC;
layout(location = 6) in vec3 aEdgeD;
layout(location = 7) in vec3 aNormalB;
layout(location = 8) in vec3 aNormalC;
layout(location = 9) in vec2 aUvB;
layout(location = 10) in vec2 aUvC;

out vec2 gFinUv;
out vec2 gSkinUv;
out vec3 gNormal;
out float gFade;
flat out int gLabTodo;

vec3 toWorld(vec3 p)
{
    return (uModel * vec4(p, 1.0)).xyz;
}

void main()
{
    vec3 a = toWorld(aEdgeA), b = toWorld(aEdgeB), c = toWorld(aEdgeC), d = toWorld(aEdgeD);
    mat3 normals = normalMatrix(uModel);
    vec3 nB = normalize(normals * aNormalB), nC = normalize(normals * aNormalC);
    // The quad as a strip: 0 B at the root, 1 C at the root, 2 B's tip, 3 C's tip.
    bool atC = gl_VertexID == 1 || gl_VertexID == 3;
    bool atTip = gl_VertexID >= 2;
    gSkinUv = atC ? aUvC : aUvB;
    gNormal = atC ? nC : nB;
    if (!isSilhouette(uEye, a, b, c, d)) {
        // No fin: all four corners at one point outside the view, so nothing is drawn.
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        gFinUv = vec2(0.0);
        gFade = 0.0;
        gLabTodo = 0;
        return;
    }
    vec3 topB = b + nB * uFurLength;
    vec3 topC = c + nC * uFurLength;
    vec3 n = nB + nC;
    vec3 toEye = normalize(uEye - 0.5 * (b + c));
    gFade = dot(n, n) > 1e-12 ? 1.0 - abs(dot(toEye, normalize(n))) : 1.0;
    float u = length(c - b) / uFurLength;
    vec3 p = atTip ? (atC ? topC : topB) : (atC ? c : b);
    gl_Position = uProjection * uView * vec4(p, 1.0);
    gFinUv = vec2(atC ? u : 0.0, atTip ? 1.0 : 0.0);
    gLabTodo = gLabTodoReached ? 1 : 0;
}
