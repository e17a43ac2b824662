// Variant of solution/06-textures/glow.glsl, used instead of it in stage 08 when
// RAYLAB_SHARED_WORK is defined (the demo, and raylab bench's "shared"
// lever). Not part of any lab: students never see this file.
//
// The glow asks what the primary ray meets first - a question trace() has
// already asked of the same ray. Here the answer is the one findClosest
// kept from the pixel's first search (pixelFirstHit, in this variant's
// find_closest.glsl), so the program holds no second search at all: on
// llvmpipe, which runs the code of every branch for 8 pixels in lock step,
// that search cost every pixel, halo or not (5% of a pro frame). Same
// picture.
vec3 sunGlow(Ray ray)
{
    if (uGlowSphere < 0) return vec3(0.0);
    int sun = max(uGlowSphere, 0);
    vec3 c = uSpheres[sun].xyz;
    float r = uSpheres[sun].w;
    float tc = dot(c - ray.origin, ray.dir);
    if (tc < 0.0) return vec3(0.0);
    float dist = length(ray.origin + tc * ray.dir - c);
    float x = max(dist - r, 0.0) / (uGlowSize * r);
    if (x >= 1.0) return vec3(0.0);
    Hit blocker = pixelFirstHit;
    if (blocker.id >= 0 && blocker.id != objectId(KIND_SPHERE, uGlowSphere) && blocker.t < tc) return vec3(0.0);
    float fade = 1.0 - x;
    return uGlowColor * fade * fade * fade;
}
