// Where does a ray meet a disc (a round, flat plate)?
//
// A disc lies in the plane through `center` with normal `normal`; a point of
// that plane is on the disc when its distance to the centre is at most
// `radius`. So: hit the plane first, then test the distance.
// Returns t > T_MIN, or NO_HIT.
float intersectDisc(Ray ray, vec3 center, vec3 normal, float radius)
{
    float t = intersectPlane(ray, normal, dot(normal, center));
    if (t == NO_HIT) return NO_HIT;
    vec3 fromCenter = ray.origin + t * ray.dir - center;
    return dot(fromCenter, fromCenter) <= radius * radius ? t : NO_HIT;
}
