// Where does a ray first meet a sphere?
//
// TODO(01.a): where the ray first meets the sphere.
// intersectSphere returns the distance t along the ray to its first hit
// with the sphere (centre `center`, radius `radius` > 0): the
// smallest t > T_MIN with |ray.origin + t ray.dir - center| = radius, or
// NO_HIT when there is none.
//  - ray.dir is a unit vector, so t is a distance in scene units.
//  - The camera may be inside the sphere: the hit is then where the ray
//    leaves it. A sphere wholly behind the ray's origin is not hit.
//  - A small sphere far away must still be hit where it is: the guide's
//    section 2 says which formula loses it to rounding.
// Checked by: raylab check --stage 01 (function intersectSphere; all views).
float intersectSphere(Ray ray, vec3 center, float radius)
{
    vec3 L = ray.origin - center;
    float half_b = dot(L, ray.dir);
    vec3 perp = L - half_b * ray.dir;
    float disc = radius * radius - dot(perp, perp);
    if (disc < 0.0) return NO_HIT;
    float root = sqrt(disc);
    float q = half_b >= 0.0 ? -half_b - root : -half_b + root;
    if (q == 0.0) return NO_HIT;
    float c = dot(L, L) - radius * radius;
    float near = min(q, c / q), far = max(q, c / q);
    if (near > T_MIN) return near;
    if (far > T_MIN) return far;
    return NO_HIT;
}
