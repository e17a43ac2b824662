// The nearest object along a ray: a linear minimum search over all spheres.
// Returns true and fills `hit` (distance and sphere index) when something was
// hit, false otherwise.
bool findClosest(Ray ray, out Hit hit)
{
    // TODO(01.b): the nearest sphere along the ray.
    // Fill `hit` with the nearest sphere the ray meets: its distance
    // t (from intersectSphere) and its index i (uSpheres[i].xyz is the centre,
    // .w the radius, i < uSphereCount). Return true when the ray meets a
    // sphere; otherwise false, with hit = Hit(T_FAR, -1).
    // Checked by: raylab check --stage 01 (function findClosest; views front, close-overlap).
    hit = Hit(T_FAR, -1);
    int i = 0;
    while (i < uSphereCount) {
        float t = intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w);
        if (t != NO_HIT && t < hit.t) { hit.t = t; hit.id = i; }
        i++;
    }
    return hit.id != -1;
}
