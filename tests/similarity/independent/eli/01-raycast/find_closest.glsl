/*
 * findClosest -- Eli's version.
 * Walk over the scene's spheres and remember the one with the smallest
 * positive distance. Missed spheres (NO_HIT, which is negative) are skipped.
 */
bool findClosest(Ray ray, out Hit hit)
{
    float bestDist = T_FAR;
    int bestIndex = -1;

    int k = 0;
    while (k < uSphereCount) {
        vec4 sphere = uSpheres[k];
        float dist = intersectSphere(ray, sphere.xyz, sphere.w);
        bool counts = dist > 0.0;
        if (counts && dist < bestDist) {
            bestDist = dist;
            bestIndex = k;
        }
        k = k + 1;
    }

    hit.t = bestDist;
    hit.id = bestIndex;
    return bestIndex != -1;
}
