// Where does a ray first meet a sphere?
//
// A point p is on the sphere when |p - center| = radius. Put the ray's point
// p(t) = o + t d in: with oc = o - center and |d| = 1,
//     t^2 + 2 (oc . d) t + (oc . oc - radius^2) = 0.
// Returns the smallest t > T_MIN, or NO_HIT.
float intersectSphere(Ray ray, vec3 center, float radius)
{
    vec3 oc = ray.origin - center;
    float b = dot(oc, ray.dir);               // half the linear coefficient
    float c = dot(oc, oc) - radius * radius;
    float h = b * b - c;                      // a quarter of the discriminant
    if (h < 0.0) return NO_HIT;               // the line misses the sphere
    h = sqrt(h);
    float t = -b - h;                         // the near root: entering the sphere
    if (t <= T_MIN) t = -b + h;               // entry behind us: we are inside, take the exit
    return t > T_MIN ? t : NO_HIT;            // both behind us: no hit
}
