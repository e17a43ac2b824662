//@open
//@ // Where does a ray first meet a sphere?
//@ //
//@ // TODO(01.a): where the ray first meets the sphere.
//@ // intersectSphere returns the distance t along the ray to its first hit
//@ // with the sphere (centre `center`, radius `radius` > 0): the
//@ // smallest t > T_MIN with |ray.origin + t ray.dir - center| = radius, or
//@ // NO_HIT when there is none.
//@ //  - ray.dir is a unit vector, so t is a distance in scene units.
//@ //  - The camera may be inside the sphere: the hit is then where the ray
//@ //    leaves it. A sphere wholly behind the ray's origin is not hit.
//@ //  - A small sphere far away must still be hit where it is: the guide's
//@ //    section 2 says which formula loses it to rounding.
//@ // Checked by: raylab check --stage 01 (function intersectSphere; all views).
//@ float intersectSphere(Ray ray, vec3 center, float radius)
//@ {
//@     labTodo();
//@     return NO_HIT;
//@ }
//@guided
// Where does a ray first meet a sphere?
//
// A point p is on the sphere when |p - center| = radius. Put the ray's point
// p(t) = o + t d in: with oc = o - center and |d| = 1,
//     t^2 + 2 (oc . d) t + (oc . oc - radius^2) = 0.
// Returns the smallest t > T_MIN, or NO_HIT.
float intersectSphere(Ray ray, vec3 center, float radius)
{
    // TODO(01.a): solve the quadratic above for the nearest hit in front of
    // the ray origin. Return NO_HIT when the ray misses the sphere or the
    // sphere lies behind the origin. The camera may be inside a sphere.
    // For a small sphere far away b*b - c cancels (guide, section 2): use
    //     h = radius^2 - |oc - b d|^2
    // and the roots q = -b - s (square root of h) and c / q (they multiply
    // to c; the smaller is the near one), with s = 1 for b >= 0, else -1
    // (not GLSL's sign(b): that is 0 for b = 0, a ray from the centre).
    // Checked by: raylab check --stage 01 (all views).
    //@solution
    vec3 oc = ray.origin - center;
    float b = dot(oc, ray.dir);               // half the linear coefficient
    float c = dot(oc, oc) - radius * radius;
    vec3 closest = oc - b * ray.dir;          // centre to the line's closest point
    float h = radius * radius - dot(closest, closest);  // the same quarter discriminant, no cancellation
    if (h < 0.0) return NO_HIT;               // the line misses the sphere
    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(h);  // -b and the root pull the same way: no cancellation
    if (q == 0.0) return NO_HIT;              // the origin touches the sphere and the ray only grazes it
    float t0 = min(c / q, q);                 // the two roots (their product is c)
    float t1 = max(c / q, q);
    float t = t0;                             // the near root: entering the sphere
    if (t <= T_MIN) t = t1;                   // entry behind us: we are inside, take the exit
    return t > T_MIN ? t : NO_HIT;            // both behind us: no hit
    //@stub
    //@ labTodo();
    //@ return NO_HIT;
    //@end
}
//@end-open
