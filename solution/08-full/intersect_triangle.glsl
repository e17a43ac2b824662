// Where does a ray meet the triangle a, b, c? (Provided: nothing to do here.)
//
// This file replaces lab 05's Moller-Trumbore for the full demo. Moller-
// Trumbore computes the barycentric coordinates u and v of each triangle on
// its own, each with its own rounding. A ray aimed exactly at the edge two
// triangles share (the diagonal of the mirror, the edges of the glass cube)
// can then come out just outside BOTH of them: it falls through the crack,
// and a pixel of background shows through a closed surface.
// (tests/numerics/triangle_test.cpp counts such rays.)
//
// The watertight test of Woop, Benthin and Wald ("Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013) cannot crack:
//  1. Move the ray origin to 0 and shear/scale space so that the ray runs
//     along +z (kz: the direction's largest component; kx and ky the other
//     two, swapped when d[kz] < 0 so that the winding is kept). The corners
//     then need only their x and y to decide the hit.
//  2. Three 2D edge functions U, V, W say on which side of each edge the ray
//     (now the point (0, 0)) passes. The ray hits when all three have one
//     sign (either sign: both sides of a triangle count).
//  3. An edge shared by two triangles is computed from the same two sheared
//     corners in both, with the corners in one fixed order (edgeFunction),
//     so its value in one triangle is exactly minus its value in the other:
//     the ray is inside one of them or on the edge of both, never outside
//     both.
// Where an edge function is exactly 0 the ray passes through the edge (or a
// corner) within float precision. The paper recomputes such values in double
// precision to learn the exact side; GLSL 3.30 has no double, so a 0 counts
// as inside for every triangle that shares the edge: both report the hit
// (at the same t), and nothing falls through.
//
// The numerics tests and the benchmark compare it with lab 05's
// Moller-Trumbore.
// Returns t > T_MIN, or NO_HIT.

// p.x q.y - p.y q.x with p and q in one fixed order (the lexicographically
// smaller first): the same two corners give exactly opposite values in the
// two triangles that share them, even where a compiler fuses a multiply and
// an add into one rounding.
float edgeFunction(vec2 p, vec2 q)
{
    bool swapped = p.x > q.x || (p.x == q.x && p.y > q.y);
    vec2 first = swapped ? q : p;
    vec2 second = swapped ? p : q;
    float e = first.x * second.y - first.y * second.x;
    return swapped ? -e : e;
}

float intersectTriangle(Ray ray, vec3 a, vec3 b, vec3 c)
{
    // 1. The axis the ray runs along most, and the shear that makes it +z.
    vec3 d = ray.dir;
    vec3 absD = abs(d);
    int kz = absD.x > absD.y ? (absD.x > absD.z ? 0 : 2) : (absD.y > absD.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.0) { int swap = kx; kx = ky; ky = swap; }
    float sz = 1.0 / d[kz];
    float sx = d[kx] * sz;
    float sy = d[ky] * sz;

    // The corners relative to the origin, sheared: only x and y matter for
    // the hit; z (scaled) gives the distance.
    vec3 A = a - ray.origin;
    vec3 B = b - ray.origin;
    vec3 C = c - ray.origin;
    vec2 a2 = vec2(A[kx] - sx * A[kz], A[ky] - sy * A[kz]);
    vec2 b2 = vec2(B[kx] - sx * B[kz], B[ky] - sy * B[kz]);
    vec2 c2 = vec2(C[kx] - sx * C[kz], C[ky] - sy * C[kz]);

    // 2. The edge functions: twice the signed areas of the triangles the
    // origin forms with each edge.
    float U = edgeFunction(c2, b2);
    float V = edgeFunction(a2, c2);
    float W = edgeFunction(b2, a2);
    if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return NO_HIT;
    float det = U + V + W;
    if (det == 0.0) return NO_HIT;  // the ray runs in the triangle's plane
    // Corners on one line (or the same corner twice): no area, no normal -
    // surfaceAt() would normalise a zero vector into NaN. The sheared
    // corners need not lie exactly on a line after rounding, so the
    // triangle itself is tested (only for the few rays that got this far).
    vec3 normal = cross(b - a, c - a);
    if (dot(normal, normal) == 0.0) return NO_HIT;

    // 3. The distance: the barycentric mix of the corners' scaled z.
    float T = U * (sz * A[kz]) + V * (sz * B[kz]) + W * (sz * C[kz]);
    float t = T / det;
    return t > T_MIN ? t : NO_HIT;
}
