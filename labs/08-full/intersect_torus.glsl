// A torus (a ring doughnut) in its own frame: centred at the origin, axis
// +z, distance R from the centre to the middle of the tube, tube radius r.
// A point p is on its surface when
//     f(p) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p.x^2 + p.y^2) = 0.
// Along a ray o + t d (|d| = 1) that is a quartic in t: up to four hits.
#include "solve_quartic.glsl"

// The nearest t > T_MIN where the ray (in the torus frame) meets the torus,
// or NO_HIT. (Provided.)
float intersectTorusLocal(Ray ray, float R, float r)
{
    // Float precision: the quartic's coefficients grow with the fourth power
    // of the distance to the torus, and the roots drown in rounding error a
    // few radii away (the seed thesis saw exactly this). So first jump to
    // where the ray enters the torus's bounding sphere and solve from there.
    float bound = R + r;
    float b = dot(ray.origin, ray.dir);
    float c = dot(ray.origin, ray.origin) - bound * bound;
    float h = b * b - c;
    if (h < 0.0) return NO_HIT;          // misses the bounding sphere
    float tEnter = max(-b - sqrt(h), 0.0);
    if (-b + sqrt(h) <= T_MIN) return NO_HIT;  // the sphere is behind the ray
    vec3 o = ray.origin + tEnter * ray.dir;
    vec3 d = ray.dir;

    float m = dot(o, o);
    float n = dot(o, d);
    float k = m + R * R - r * r;
    float R4 = 4.0 * R * R;
    vec4 coefficients = vec4(4.0 * n,
                             4.0 * n * n + 2.0 * k - R4 * (d.x * d.x + d.y * d.y),
                             4.0 * n * k - 2.0 * R4 * (o.x * d.x + o.y * d.y),
                             k * k - R4 * (o.x * o.x + o.y * o.y));
    vec4 roots;
    int count = solveQuartic(coefficients, roots);
    float best = T_FAR;
    for (int i = 0; i < count; ++i) {
        float t = tEnter + roots[i];
        if (t > T_MIN && t < best) best = t;
    }
    return best < T_FAR ? best : NO_HIT;
}

// The unit outward normal of the torus at a surface point p (torus frame).
// The normal of an implicit surface f(p) = 0 is the direction of the
// gradient of f.
vec3 torusNormalLocal(vec3 p, float R, float r)
{
    return normalize((dot(p, p) + R * R - r * r) * p - 2.0 * R * R * vec3(p.xy, 0.0));
}

// World-space versions for torus number i of the scene.
float intersectTorus(Ray ray, int i)
{
    mat3 toLocal = uTorusToLocal[i];
    Ray local = Ray(toLocal * (ray.origin - uTori[i].xyz), toLocal * ray.dir);
    return intersectTorusLocal(local, uTori[i].w, uTorusMinor[i]);
}

vec3 torusNormal(int i, vec3 point)
{
    mat3 toLocal = uTorusToLocal[i];
    // toLocal is a rotation: its transpose turns local directions back.
    return transpose(toLocal) * torusNormalLocal(toLocal * (point - uTori[i].xyz), uTori[i].w, uTorusMinor[i]);
}
