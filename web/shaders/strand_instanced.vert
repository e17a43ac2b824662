// The web build's fur shader (stage f4): WebGL 2 has no geometry shaders,
// so each strand is an instanced line strip - instance = (triangle, strand),
// vertex = point along the strand - and this vertex shader places the
// points as strand.geom does natively, with the student's strandPoint()
// (strand_point.glsl). It feeds strand.frag unchanged. The triangle's corners
// arrive as per-instance attributes that advance once every
// STRANDS_PER_TRIANGLE instances. (Students need not change this file.)
#include "fur_uniforms.glsl"
#include "lab_todo.glsl"
#include "normal_matrix.glsl"
#include "strand_point.glsl"

layout(location = 3) in vec3 aCorner0;
layout(location = 4) in vec3 aCorner1;
layout(location = 5) in vec3 aCorner2;
layout(location = 6) in vec3 aNormal0;
layout(location = 7) in vec3 aNormal1;
layout(location = 8) in vec3 aNormal2;
layout(location = 9) in vec2 aUv0;
layout(location = 10) in vec2 aUv1;
layout(location = 11) in vec2 aUv2;

out vec3 gWorldPos;
out vec3 gTangent;
out vec3 gNormal;
out vec2 gUv;
out float gS;
flat out int gLabTodo;

// strand.geom's hash: a number in [0, 1) from an integer, the same on every GPU.
float hash01(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return float(x >> 8) / 16777216.0;
}

void main()
{
    int triangle = gl_InstanceID / STRANDS_PER_TRIANGLE;
    int i = gl_InstanceID % STRANDS_PER_TRIANGLE;
    int k = gl_VertexID;  // 0 (root) .. STRAND_SEGMENTS (tip)
    mat3 normals = normalMatrix(uModel);
    vec3 a = (uModel * vec4(aCorner0, 1.0)).xyz;
    vec3 b = (uModel * vec4(aCorner1, 1.0)).xyz;
    vec3 c = (uModel * vec4(aCorner2, 1.0)).xyz;
    float area = 0.5 * length(cross(b - a, c - a));
    float jitter = hash01(uint(triangle));
    int count = int(min(area * uStrandDensity + jitter, float(STRANDS_PER_TRIANGLE)));
    if (i >= count) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // no such strand: off screen, not drawn
        gWorldPos = gTangent = gNormal = vec3(0.0);
        gUv = vec2(0.0);
        gS = 0.0;
        gLabTodo = 0;
        return;
    }
    vec2 r = fract(vec2(0.7548776662, 0.5698402910) * float(i + 1) + jitter);
    if (r.x + r.y > 1.0) r = 1.0 - r;
    vec3 w = vec3(1.0 - r.x - r.y, r.x, r.y);
    vec3 root = w.x * a + w.y * b + w.z * c;
    vec3 n0 = normalize(normals * aNormal0), n1 = normalize(normals * aNormal1), n2 = normalize(normals * aNormal2);
    vec3 normal = normalize(w.x * n0 + w.y * n1 + w.z * n2);
    float s = float(k) / float(STRAND_SEGMENTS);
    vec3 p = strandPoint(root, normal, s, uFurLength, uGravity);
    // As natively: the tangent points to the next point; the tip keeps the
    // last segment's direction.
    vec3 tangent = k < STRAND_SEGMENTS
        ? strandPoint(root, normal, min(s + 1.0 / float(STRAND_SEGMENTS), 1.0), uFurLength, uGravity) - p
        : p - strandPoint(root, normal, 1.0 - 1.0 / float(STRAND_SEGMENTS), uFurLength, uGravity);
    gl_Position = uProjection * uView * vec4(p, 1.0);
    gWorldPos = p;
    gTangent = tangent;
    gNormal = normal;
    gUv = w.x * aUv0 + w.y * aUv1 + w.z * aUv2;
    gS = s;
    gLabTodo = gLabTodoReached ? 1 : 0;
}
