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
    vec3 centerToOrigin = ray.origin - center;
    float projection = dot(centerToOrigin, ray.dir);
    // distance from the centre to the ray's line, squared, without cancellation
    vec3 closestPoint = centerToOrigin - projection * ray.dir;
    float halfChordSquared = radius * radius - dot(closestPoint, closestPoint);
    if (halfChordSquared < 0.0) {
        return NO_HIT;
    }
    float halfChord = sqrt(halfChordSquared);
    float signOfB = 1.0;
    if (projection < 0.0) {
        signOfB = -1.0;
    }
    float big = -projection - signOfB * halfChord;
    if (big == 0.0) {
        return NO_HIT;
    }
    float constant = dot(centerToOrigin, centerToOrigin) - radius * radius;
    float small = constant / big;
    float first = min(big, small);
    float second = max(big, small);
    if (first > T_MIN) {
        return first;
    }
    if (second > T_MIN) {
        return second;
    }
    return NO_HIT;
}
