//@open
//@ // The nearest object along a ray, of every kind. Returns true and fills
//@ // `hit` (distance and object id, see scene_objects.glsl) when something
//@ // was hit, false otherwise.
//@guided
// The nearest object along a ray: a linear minimum search over every object
// of every kind. Returns true and fills `hit` (distance and object id, see
// scene_objects.glsl) when something was hit, false otherwise. (Provided:
// lab 01's search, extended to the new kinds.)
//@end-open
void keepNearer(inout Hit hit, float t, int kind, int index)
{
    if (t != NO_HIT && t < hit.t) hit = Hit(t, objectId(kind, index));
}

bool findClosest(Ray ray, out Hit hit)
{
    //@open
    //@ // TODO(05.f): the nearest object of every kind.
    //@ // Lab 01's search over every object of every kind: spheres,
    //@ // planes (uPlanes[i].xyz the normal, .w the offset), discs (uDiscs[i].xyz
    //@ // the centre, .w the radius, uDiscNormals[i]), triangles (corners
    //@ // uTriangleVertices[3 i .. 3 i + 2]) and tori (intersectTorus(ray, i)),
    //@ // i below each kind's count (uPlaneCount, ...). keepNearer keeps the
    //@ // nearest with its object id.
    //@ // Checked by: raylab check --stage 05 (function findClosestEveryKind; views front, floor-level, mirror-back, torus-closeup).
    //@ labTodo();
    //@ hit = Hit(T_FAR, -1);
    //@ return hit.id >= 0;
    //@guided
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
    //@end-open
}
