//@open
//@ // Where does a ray meet the triangle a, b, c?
//@ //
//@ // TODO(05.c): where the ray meets a triangle.
//@ // IntersectTriangle returns the distance t > T_MIN at which the
//@ // ray meets the triangle (its edges included), or NO_HIT, with the
//@ // Moller-Trumbore algorithm (guide, section 4): no plane equation, no
//@ // square root.
//@ //  - Both sides count: a mirror seen from behind, the inside faces of a
//@ //    glass cube.
//@ //  - A ray parallel to the triangle's plane misses it: treat a determinant
//@ //    of magnitude below 1e-10 as zero.
//@ // Checked by: raylab check --stage 05 (function intersectTriangle; views front, mirror-back, cube-closeup).
//@ float intersectTriangle(Ray ray, vec3 a, vec3 b, vec3 c)
//@ {
//@     labTodo();
//@     return NO_HIT;
//@ }
//@guided
// Where does a ray meet the triangle a, b, c? (Moller-Trumbore, 1997)
//
// A point of the triangle is a + u (b - a) + v (c - a) with u >= 0, v >= 0
// and u + v <= 1 (barycentric coordinates). Setting it equal to o + t d
// gives three linear equations in t, u, v; Cramer's rule solves them with
// cross and dot products only:
//     e1 = b - a, e2 = c - a, p = d x e2, det = e1 . p
//     s = o - a:   u = (s . p) / det
//     q = s x e1:  v = (d . q) / det,   t = (e2 . q) / det
// det is 0 when the ray runs parallel to the triangle's plane. Its sign says
// which side the ray comes from - both sides count (a mirror seen from
// behind, the inside faces of a glass cube).
// Returns t > T_MIN, or NO_HIT.
float intersectTriangle(Ray ray, vec3 a, vec3 b, vec3 c)
{
    // TODO(05.c): compute det, u, v and t as above; reject the ray when
    // |det| < 1e-10, when u or v leaves [0, 1], when u + v > 1, or when
    // t <= T_MIN.
    // Checked by: raylab check --stage 05 (views front, mirror-back, cube-closeup).
    //@solution
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
    //@stub
    //@ labTodo();
    //@ return NO_HIT;
    //@end
}
//@end-open
