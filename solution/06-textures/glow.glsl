// A halo around the sun (key G): light scattered in the air - or in the eye -
// makes a bright source look bigger than it is. Faked here for primary rays:
// the closer a ray passes to the sun's centre, the more of the glow colour
// it gets, unless something in front of the sun blocks the view.
//
//   c, r:  the sun sphere's centre and radius (uSpheres[uGlowSphere])
//   tc = dot(c - o, d)          where along the ray it passes closest to c
//   dist = |o + tc d - c|        how close it gets
//   x = max(dist - r, 0) / (uGlowSize * r)     0 at the sun's rim, 1 at the halo's edge
//   glow = uGlowColor * (1 - x)^3 for x < 1, else nothing
vec3 sunGlow(Ray ray)
{
    //@open
    //@ // TODO(06.d): the glow around the sun.
    //@ // The glow above for the sun sphere uSpheres[uGlowSphere] (none
    //@ // when uGlowSphere < 0), nothing when the sun is behind the eye or when
    //@ // something other than the sun lies on the ray before its closest point.
    //@ // An index below 0 does not compile where uGlowSphere is a constant -1:
    //@ // index with max(uGlowSphere, 0).
    //@ // Checked by: raylab check --stage 06 (function sunGlow; views sun-glow, sun-behind-moon, away-from-sun).
    //@ labTodo();
    //@ return vec3(0.0);
    //@guided
    if (uGlowSphere < 0) return vec3(0.0);
    // (max: in a program specialised to a scene without a sun, uGlowSphere
    // is the constant -1, and a constant index below 0 does not compile.)
    int sun = max(uGlowSphere, 0);
    vec3 c = uSpheres[sun].xyz;
    float r = uSpheres[sun].w;
    // TODO(06.d): the glow above. No glow when the sun is behind the eye
    // (tc < 0) or when findClosest finds something other than the sun
    // closer than tc.
    // Checked by: raylab check --stage 06 (views sun-glow, sun-behind-moon, away-from-sun; sunGlow).
    //@solution
    float tc = dot(c - ray.origin, ray.dir);
    if (tc < 0.0) return vec3(0.0);
    float dist = length(ray.origin + tc * ray.dir - c);
    float x = max(dist - r, 0.0) / (uGlowSize * r);
    if (x >= 1.0) return vec3(0.0);
    // The halo test first: findClosest is a whole ray, and most pixels are
    // outside the halo (pro: 5 in 6 of its glow rays were not needed).
    Hit blocker;
    if (findClosest(ray, blocker) && blocker.id != objectId(KIND_SPHERE, uGlowSphere) && blocker.t < tc) return vec3(0.0);
    float fade = 1.0 - x;
    return uGlowColor * fade * fade * fade;
    //@stub
    //@ labTodo();
    //@ return vec3(0.0);
    //@end
    //@end-open
}
