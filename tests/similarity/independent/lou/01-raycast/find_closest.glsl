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
    float nearest = T_FAR;
    int which = -1;
    for (int sphere = 0; sphere < uSphereCount; sphere = sphere + 1) {
        vec4 s = uSpheres[sphere];
        float distanceAlongRay = intersectSphere(ray, s.xyz, s.w);
        if (distanceAlongRay == NO_HIT) {
            continue;
        }
        if (distanceAlongRay < nearest) {
            nearest = distanceAlongRay;
            which = sphere;
        }
    }
    hit = Hit(nearest, which);
    return which >= 0;
}
