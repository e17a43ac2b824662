// Variant of solution/06-textures/glow.glsl, used instead of it when
// RAYLAB_OLD_PATH is defined: the old order, kept so that `raylab bench`
// can show what the new one saves (its "old-path" row). It looks for a blocker before it knows whether the pixel is in the
// halo at all, so every pixel in front of the sun casts a second primary ray.
// Not part of any lab: students never see this file.
vec3 sunGlow(Ray ray)
{
    if (uGlowSphere < 0) return vec3(0.0);
    int sun = max(uGlowSphere, 0);
    vec3 c = uSpheres[sun].xyz;
    float r = uSpheres[sun].w;
    float tc = dot(c - ray.origin, ray.dir);
    if (tc < 0.0) return vec3(0.0);
    Hit blocker;
    if (findClosest(ray, blocker) && blocker.id != objectId(KIND_SPHERE, uGlowSphere) && blocker.t < tc) return vec3(0.0);
    float dist = length(ray.origin + tc * ray.dir - c);
    float x = max(dist - r, 0.0) / (uGlowSize * r);
    if (x >= 1.0) return vec3(0.0);
    float fade = 1.0 - x;
    return uGlowColor * fade * fade * fade;
}
