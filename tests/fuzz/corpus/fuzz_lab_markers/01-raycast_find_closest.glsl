// The nearest object along a ray: a linear minimum search over all spheres.
// Returns true and fills `hit` (distance and sphere index) when something was
// hit, false otherwise.
bool findClosest(Ray ray, out Hit hit)
{
    hit = Hit(T_FAR, -1);
    // TODO(01.b): test every sphere (uSpheres[i].xyz is its centre, .w its
    // radius, i < uSphereCount) and keep the hit with the smallest t.
    // Checked by: raylab check --stage 01 (views front, close-overlap; findClosest).
    //@solution
    for (int i = 0; i < uSphereCount; ++i) {
        float t = intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w);
        if (t != NO_HIT && t < hit.t) hit = Hit(t, i);
    }
    //@stub
    //@ labTodo();
    //@end
    return hit.id >= 0;
}
