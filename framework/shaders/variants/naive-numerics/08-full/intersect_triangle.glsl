// Variant of solution/08-full/intersect_triangle.glsl,
// used instead of it when RAYLAB_NAIVE_NUMERICS is defined
// (raylab bench, tests/numerics).
// Not part of any lab: students never see this file.

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
// Compiling with RAYLAB_NAIVE_NUMERICS defined gives lab 05's Moller-Trumbore
// instead (for the numerics tests and the benchmark).
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
    // Lab 05's Moller-Trumbore.
    vec3 e1 = b - a;
    vec3 e2 = c - a;
    vec3 p = cross(ray.dir, e2);
    float det = dot(e1, p);
    if (abs(det) < 1e-10) return NO_HIT;
    float invDet = 1.0 / det;
    vec3 s = ray.origin - a;
    float u = dot(s, p) * invDet;
    if (u < 0.0 || u > 1.0) return NO_HIT;
    vec3 q = cross(s, e1);
    float v = dot(ray.dir, q) * invDet;
    if (v < 0.0 || u + v > 1.0) return NO_HIT;
    float t = dot(e2, q) * invDet;
    return t > T_MIN ? t : NO_HIT;
}
