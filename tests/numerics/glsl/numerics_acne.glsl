// For tests/numerics/offset_test.cpp: a primary ray hits a surface (the
// solution's own intersection, in float), and from the hit point a shadow
// ray toward a light and the reflected ray start where the tracer starts
// them - the point put back onto the surface (surfaceAt() of stages 04-05),
// then offsetRayOrigin(point, side) - and are tested against the SAME
// surface. The surface is convex or flat and the new rays leave it, so any
// hit there is acne. Include after intersect_sphere.glsl, intersect_plane.glsl
// and ray_offset.glsl.
//
// Returns (t of the primary hit or NO_HIT, t of the shadow ray's self-hit or
// NO_HIT, t of the reflected ray's self-hit or NO_HIT, 1).

vec4 sphereAcne(vec3 eye, vec3 dir, vec3 center, float radius, vec3 light)
{
    float t = intersectSphere(Ray(eye, dir), center, radius);
    if (t == NO_HIT) return vec4(NO_HIT, NO_HIT, NO_HIT, 1.0);
    vec3 point = eye + t * dir;
    vec3 normal = normalize(point - center);  // outward: the eye is outside
    point = center + radius * normal;         // back onto the sphere, as surfaceAt() does
    if (dot(dir, normal) > 0.0) normal = -normal;  // faces the incoming ray, as in trace()
    vec3 toLight = normalize(light - point);
    vec3 side = dot(normal, toLight) >= 0.0 ? normal : -normal;  // as lightVisible() chooses it
    float shadow = intersectSphere(Ray(offsetRayOrigin(point, side), toLight), center, radius);
    float reflected = intersectSphere(Ray(offsetRayOrigin(point, normal), reflect(dir, normal)), center, radius);
    return vec4(t, shadow, reflected, 1.0);
}

vec4 planeAcne(vec3 eye, vec3 dir, vec3 planeNormal, float offset, vec3 light)
{
    float t = intersectPlane(Ray(eye, dir), planeNormal, offset);
    if (t == NO_HIT) return vec4(NO_HIT, NO_HIT, NO_HIT, 1.0);
    vec3 point = eye + t * dir;
    point -= planeNormal * (dot(planeNormal, point) - offset);  // back onto the plane, as surfaceAt() does
    vec3 normal = dot(dir, planeNormal) < 0.0 ? planeNormal : -planeNormal;  // faces the incoming ray
    vec3 toLight = normalize(light - point);
    vec3 side = dot(normal, toLight) >= 0.0 ? normal : -normal;
    float shadow = intersectPlane(Ray(offsetRayOrigin(point, side), toLight), planeNormal, offset);
    float reflected = intersectPlane(Ray(offsetRayOrigin(point, normal), reflect(dir, normal)), planeNormal, offset);
    return vec4(t, shadow, reflected, 1.0);
}

// The torus of lab 05 in its own frame (include intersect_torus.glsl): the
// torus is not convex, so a reflected ray may rightly hit it again - but not
// within a hair of where it starts. Returns (t, shadow ray's t, reflected
// ray's t, 1) like the others.
vec4 torusAcne(vec3 eye, vec3 dir, float R, float r, vec3 light)
{
    float t = intersectTorusLocal(Ray(eye, dir), R, r);
    if (t == NO_HIT) return vec4(NO_HIT, NO_HIT, NO_HIT, 1.0);
    vec3 point = eye + t * dir;
    vec3 normal = torusNormalLocal(point, R, r);
    if (dot(dir, normal) > 0.0) normal = -normal;
    vec3 toLight = normalize(light - point);
    vec3 side = dot(normal, toLight) >= 0.0 ? normal : -normal;
    float shadow = intersectTorusLocal(Ray(offsetRayOrigin(point, side), toLight), R, r);
    float reflected = intersectTorusLocal(Ray(offsetRayOrigin(point, normal), reflect(dir, normal)), R, r);
    return vec4(t, shadow, reflected, 1.0);
}
