//@open
//@ // Where does a ray meet a disc (a round, flat plate)?
//@ //
//@ // TODO(05.b): where the ray meets a disc.
//@ // IntersectDisc returns the distance t > T_MIN at which the ray
//@ // meets the disc - the points of the plane through `center` with unit
//@ // normal `normal` no farther than `radius` from the centre (its rim
//@ // included) - or NO_HIT. intersectPlane (05.a) may help.
//@ // Checked by: raylab check --stage 05 (function intersectDisc; views front, disc-closeup).
//@ float intersectDisc(Ray ray, vec3 center, vec3 normal, float radius)
//@ {
//@     labTodo();
//@     return NO_HIT;
//@ }
//@guided
// Where does a ray meet a disc (a round, flat plate)?
//
// A disc lies in the plane through `center` with normal `normal`; a point of
// that plane is on the disc when its distance to the centre is at most
// `radius`. So: hit the plane first, then test the distance.
// Returns t > T_MIN, or NO_HIT.
float intersectDisc(Ray ray, vec3 center, vec3 normal, float radius)
{
    // TODO(05.b): use intersectPlane (the offset of the disc's plane is
    // dot(normal, center)), then keep the hit only within the radius.
    // Comparing squared lengths avoids a square root.
    // Checked by: raylab check --stage 05 (views front, disc-closeup).
    //@solution
    float t = intersectPlane(ray, normal, dot(normal, center));
    if (t == NO_HIT) return NO_HIT;
    vec3 fromCenter = ray.origin + t * ray.dir - center;
    return dot(fromCenter, fromCenter) <= radius * radius ? t : NO_HIT;
    //@stub
    //@ labTodo();
    //@ return NO_HIT;
    //@end
}
//@end-open
