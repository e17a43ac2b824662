/*
 * intersectSphere -- Eli's version.
 *
 * Solve t^2 + 2*halfB*t + cTerm = 0 for the ray p(t) = origin + t*dir.
 * Both the discriminant and the roots are computed in the forms that do
 * not subtract two large, nearly equal floats.
 */

// +1 for zero and positive numbers, -1 for negative ones (unlike sign()).
float eliSignNoZero(float value)
{
    return value < 0.0 ? -1.0 : 1.0;
}

float intersectSphere(Ray ray, vec3 center, float radius)
{
    float result = NO_HIT;
    float radiusSq = radius * radius;
    vec3 centerToOrigin = ray.origin - center;
    float halfB = dot(ray.dir, centerToOrigin);

    /* Pythagoras: distance of the centre from the ray's line, squared. */
    vec3 closestOffset = centerToOrigin - ray.dir * halfB;
    float quarterDisc = radiusSq - dot(closestOffset, closestOffset);

    if (quarterDisc >= 0.0) {
        float cTerm = dot(centerToOrigin, centerToOrigin) - radiusSq;
        float largeRoot = -(halfB + eliSignNoZero(halfB) * sqrt(quarterDisc));
        if (largeRoot != 0.0) {
            float otherRoot = cTerm / largeRoot;     /* product of roots = cTerm */
            float entryT = min(largeRoot, otherRoot);
            float exitT = max(largeRoot, otherRoot);
            if (entryT > T_MIN) {
                result = entryT;
            } else if (exitT > T_MIN) {
                result = exitT;                      /* eye inside the sphere */
            }
        }
    }
    return result;
}
