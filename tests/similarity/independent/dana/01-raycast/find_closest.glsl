// The nearest object along a ray: a linear minimum search over all spheres.
// Returns true and fills `hit` (distance and sphere index) when something was
// hit, false otherwise.
bool findClosest(Ray ray, out Hit hit)
{
    hit = Hit(T_FAR, -1);
    for (int i = 0; i < uSphereCount; ++i) {
        float t = intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w);
        if (t < 0.0 || t >= hit.t) continue;   // miss (NO_HIT) or farther
        hit = Hit(t, i);
    }
    return hit.id >= 0;
}
