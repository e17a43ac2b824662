// A ray against an axis-aligned box (the slab test), for stage 08's BVH
// walk and its groups of triangles. (Students need not change this file.)

// 1 / d for the slab test. 1/0 would give 0 * inf = NaN for a ray exactly on
// a box face: a tiny direction component instead gives a huge finite slope.
vec3 inverseDirection(vec3 d)
{
    return 1.0 / vec3(abs(d.x) < 1e-20 ? 1e-20 : d.x, abs(d.y) < 1e-20 ? 1e-20 : d.y, abs(d.z) < 1e-20 ? 1e-20 : d.z);
}

// Where the ray enters the box lo..hi (0 when it starts inside), or T_FAR
// when it misses it or reaches it only beyond tMax.
float enterBox(vec3 origin, vec3 invDir, vec3 lo, vec3 hi, float tMax)
{
    vec3 t0 = (lo - origin) * invDir;
    vec3 t1 = (hi - origin) * invDir;
    vec3 tNear = min(t0, t1);
    vec3 tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    return enter <= leave ? enter : T_FAR;
}
