// The surface a ray hit: point, outward normal and material. In this stage
// every object is a sphere; lab 05 adds other kinds of object here.
Surface surfaceAt(Ray ray, Hit hit)
{
    vec3 point = ray.origin + hit.t * ray.dir;
    vec3 outward = normalize(point - uSpheres[hit.id].xyz);
    // Put back onto the sphere: from a far eye, origin + t dir lies float
    // steps of the eye's coordinates off it (tests/numerics/offset_test.cpp).
    point = uSpheres[hit.id].xyz + uSpheres[hit.id].w * outward;
    return Surface(point, outward, materialOfSphere(hit.id), vec2(0.0), vec3(0.0));
}
