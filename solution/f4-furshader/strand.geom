// Stage f4, the fur shader: strands grown from each triangle by a geometry
// shader. The framework draws the mesh's triangles; each invocation gets one
// triangle and writes its strands as line strips.
//
// A geometry shader must declare the most vertices it writes, and the driver
// bounds that (GL_MAX_GEOMETRY_OUTPUT_VERTICES) and the vertices times their
// components (GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS). The framework reads
// both limits and defines STRANDS_PER_TRIANGLE and STRAND_SEGMENTS to fit
// (guide, section 5, "The output budget").
layout(triangles) in;
layout(line_strip, max_vertices = STRAND_MAX_VERTICES) out;

#include "fur_uniforms.glsl"
#include "transform.glsl"
#include "lab_todo.glsl"
#include "strand_point.glsl"

in vec3 vWorldPos[];
in vec3 vNormal[];
in vec2 vUv[];
flat in int vLabTodo[];

// 17 components per vertex with gl_Position: the framework's budget counts them.
out vec3 gWorldPos;
out vec3 gTangent;  // along the strand, toward the tip
out vec3 gNormal;   // the skin's normal at the root
out vec2 gUv;       // the skin's texture coordinate at the root
out float gS;       // 0 at the root, 1 at the tip
flat out int gLabTodo;

// A number in [0, 1) from an integer, the same on every GPU (no sin()).
float hash01(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return float(x >> 8) / 16777216.0;
}

// How many strands grow from a triangle of AREA: in proportion to the area,
// so that small and large triangles carry equally dense fur; the fraction
// becomes one more strand with probability JITTER's. At most
// STRANDS_PER_TRIANGLE. (Provided.)
int strandCount(float area, float jitter)
{
    // (Clamped before the conversion: a float past the largest int has no
    // defined int value in GLSL.)
    return int(min(area * uStrandDensity + jitter, float(STRANDS_PER_TRIANGLE)));
}

// Where strand I of a triangle grows: its barycentric weights (they add up
// to 1), well-spread points of the unit square (the R2 sequence, shifted by
// JITTER) folded into the triangle. (Provided.)
vec3 strandRootWeights(int i, float jitter)
{
    vec2 r = fract(vec2(0.7548776662, 0.5698402910) * float(i + 1) + jitter);
    if (r.x + r.y > 1.0) r = 1.0 - r;
    return vec3(1.0 - r.x - r.y, r.x, r.y);
}

void main()
{
    //@open
    //@ // TODO(f4.d): the strands of this triangle.
    //@ // The strands of this triangle (guide, sections 1, 5): their
    //@ // number strandCount(area, jitter), with jitter = hash01 of the
    //@ // triangle's gl_PrimitiveIDIn; strand i grows at the barycentric weights
    //@ // strandRootWeights(i, jitter), which also blend the corners' normals
    //@ // (normalised) and texture coordinates. Each strand is one line strip of
    //@ // STRAND_SEGMENTS + 1 vertices at s = k / STRAND_SEGMENTS, k = 0 ..
    //@ // STRAND_SEGMENTS, placed by strandPoint (uFurLength, uGravity), with
    //@ // the outputs above: gTangent from this vertex to the next one (the tip
    //@ // keeps the last segment's), gNormal and gUv those of the root, gS = s,
    //@ // gLabTodo 1 when gLabTodoReached or a corner's vLabTodo is set.
    //@ //  - Never more than STRAND_MAX_VERTICES vertices: the loops' bounds
    //@ //    must be constants the compiler can see (the output budget).
    //@ //  - Outputs are undefined after EmitVertex(): write every one for
    //@ //    every vertex.
    //@ // Checked by: raylab check --stage f4 (views fur-shader, fur-shader-side, fur-shader-shaggy, fur-shader-cube).
    //@ labTodo();
    //@guided
    vec3 a = vWorldPos[0], b = vWorldPos[1], c = vWorldPos[2];
    float area = 0.5 * length(cross(b - a, c - a));
    float jitter = hash01(uint(gl_PrimitiveIDIn));
    int count = strandCount(area, jitter);
    int todo = gLabTodoReached || vLabTodo[0] != 0 ? 1 : 0;
    for (int i = 0; i < STRANDS_PER_TRIANGLE; ++i) {
        if (i >= count) break;
        vec3 w = strandRootWeights(i, jitter);
        vec3 root = w.x * a + w.y * b + w.z * c;
        vec3 normal = normalize(w.x * vNormal[0] + w.y * vNormal[1] + w.z * vNormal[2]);
        vec2 uv = w.x * vUv[0] + w.y * vUv[1] + w.z * vUv[2];
        vec3 p = strandPoint(root, normal, 0.0, uFurLength, uGravity);
        vec3 tangent = normal;
        for (int k = 0; k <= STRAND_SEGMENTS; ++k) {
            float s = float(k) / float(STRAND_SEGMENTS);
            // The tangent points to the next point; the tip keeps the last
            // segment's direction. (Written for every vertex: outputs are
            // undefined after EmitVertex().)
            vec3 next = strandPoint(root, normal, min(s + 1.0 / float(STRAND_SEGMENTS), 1.0),
                                    uFurLength, uGravity);
            if (k < STRAND_SEGMENTS) tangent = next - p;
            gTangent = tangent;
            gl_Position = toClip(vec4(p, 1.0));
            gWorldPos = p;
            gNormal = normal;
            gUv = uv;
            gS = s;
            gLabTodo = todo | (gLabTodoReached ? 1 : 0);
            EmitVertex();
            p = next;
        }
        EndPrimitive();
    }
    //@end-open
}
