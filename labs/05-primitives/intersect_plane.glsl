// Where does a ray meet an infinite plane?
//
// The plane is every point p with dot(normal, p) = offset. Put the ray's
// point p(t) = o + t d in and solve for t:
//     t = (offset - dot(normal, o)) / dot(normal, d)
// When dot(normal, d) is (almost) 0 the ray runs parallel to the plane.
// Returns t > T_MIN, or NO_HIT.
float intersectPlane(Ray ray, vec3 normal, float offset)
{
    // TODO(05.a): solve for t as above. Return NO_HIT for a ray parallel to
    // the plane (|dot(normal, d)| < 1e-6: in float a ray lying in a tilted
    // plane still gives about 1e-7) and for a plane behind the origin.
    // Checked by: raylab check --stage 05 (views front, floor-level, from-below).
    labTodo();
    return NO_HIT;
}
