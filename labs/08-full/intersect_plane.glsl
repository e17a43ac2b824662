// Where does a ray meet an infinite plane?
//
// The plane is every point p with dot(normal, p) = offset. Put the ray's
// point p(t) = o + t d in and solve for t:
//     t = (offset - dot(normal, o)) / dot(normal, d)
// When dot(normal, d) is (almost) 0 the ray runs parallel to the plane.
// Returns t > T_MIN, or NO_HIT.
float intersectPlane(Ray ray, vec3 normal, float offset)
{
    float facing = dot(normal, ray.dir);
    if (abs(facing) < 1e-6) return NO_HIT;
    float t = (offset - dot(normal, ray.origin)) / facing;
    return t > T_MIN ? t : NO_HIT;
}
