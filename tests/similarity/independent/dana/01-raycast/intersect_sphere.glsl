// Where does a ray first meet a sphere?
//
// Returns the smallest t > T_MIN on the ray that lies on the sphere, or
// NO_HIT. Uses the cancellation-free form of the quadratic (guide, sec. 2).
float intersectSphere(Ray ray, vec3 center, float radius)
{
    vec3 oc = ray.origin - center;
    float b = dot(oc, ray.dir);
    vec3 perp = oc - b * ray.dir;               // centre -> closest point of the line
    float h = radius * radius - dot(perp, perp);
    if (h < 0.0) return NO_HIT;                 // line misses

    float c = dot(oc, oc) - radius * radius;
    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(h);
    if (q == 0.0) return NO_HIT;                // grazing from the surface: 0/0

    float t0 = min(q, c / q);
    float t1 = max(q, c / q);
    if (t0 > T_MIN) return t0;                  // sphere ahead
    if (t1 > T_MIN) return t1;                  // we are inside
    return NO_HIT;                              // behind us
}
