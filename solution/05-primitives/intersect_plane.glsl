//@open
//@ // Where does a ray meet an infinite plane?
//@ //
//@ // TODO(05.a): where the ray meets a plane.
//@ // IntersectPlane returns the distance t > T_MIN at which the
//@ // ray meets the plane of points p with dot(normal, p) = offset (`normal` a
//@ // unit vector), or NO_HIT.
//@ //  - A ray parallel to the plane never meets it, and one lying in it must
//@ //    not count either: treat |dot(normal, ray.dir)| < 1e-6 as parallel (in
//@ //    float a ray lying in a tilted plane still gives about 1e-7).
//@ //  - The plane is hit from either side.
//@ // Checked by: raylab check --stage 05 (function intersectPlane; views front, floor-level, from-below).
//@ float intersectPlane(Ray ray, vec3 normal, float offset)
//@ {
//@     labTodo();
//@     return NO_HIT;
//@ }
//@guided
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
    //@solution
    float facing = dot(normal, ray.dir);
    if (abs(facing) < 1e-6) return NO_HIT;
    float t = (offset - dot(normal, ray.origin)) / facing;
    return t > T_MIN ? t : NO_HIT;
    //@stub
    //@ labTodo();
    //@ return NO_HIT;
    //@end
}
//@end-open
