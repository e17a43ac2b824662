// The nearest object along a ray: a linear minimum search over every object
// of every kind. Returns true and fills `hit` (distance and object id, see
// scene_objects.glsl) when something was hit, false otherwise. (Provided:
// lab 01's search, extended to the new kinds.)
void keepNearer(inout Hit hit, float t, int kind, int index)
{
    if (t != NO_HIT && t < hit.t) hit = Hit(t, objectId(kind, index));
}

bool findClosest(Ray ray, out Hit hit)
{
    hit = Hit(T_FAR, -1);
    for (int i = 0; i < uSphereCount; ++i)
        keepNearer(hit, intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w), KIND_SPHERE, i);
    for (int i = 0; i < uPlaneCount; ++i)
        keepNearer(hit, intersectPlane(ray, uPlanes[i].xyz, uPlanes[i].w), KIND_PLANE, i);
    for (int i = 0; i < uDiscCount; ++i)
        keepNearer(hit, intersectDisc(ray, uDiscs[i].xyz, uDiscNormals[i], uDiscs[i].w), KIND_DISC, i);
    for (int i = 0; i < uTriangleCount; ++i)
        keepNearer(hit, intersectTriangle(ray, uTriangleVertices[3 * i], uTriangleVertices[3 * i + 1], uTriangleVertices[3 * i + 2]),
                   KIND_TRIANGLE, i);
    for (int i = 0; i < uTorusCount; ++i)
        keepNearer(hit, intersectTorus(ray, i), KIND_TORUS, i);
    return hit.id >= 0;
}
