// A torus (a ring doughnut) in its own frame: centred at the origin, axis
// +z, distance R from the centre to the middle of the tube, tube radius r.
// A point p is on its surface when
//     f(p) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p.x^2 + p.y^2) = 0.
// Along a ray o + t d (|d| = 1) that is a quartic in t: up to four hits.
#include "solve_quartic.glsl"

// Distance from p to the torus surface (negative inside the tube).
float torusDistance(vec3 p, float R, float r)
{
    return length(vec2(length(p.xy) - R, p.z)) - r;
}

// Two Newton steps on the torus's distance function along the ray: unlike
// the quartic, the distance is computed without cancellation, so the root
// lands within a few float steps of the true hit. Skipped where the ray
// grazes the surface (the step would overshoot).
float polishTorusHit(vec3 o, vec3 d, float t, float R, float r)
{
    for (int step = 0; step < 2; ++step) {
        vec3 p = o + t * d;
        float ring = length(p.xy);
        vec2 q = vec2(ring - R, p.z);
        float len = length(q);
        if (ring < 1e-12 || len < 1e-12) break;
        vec3 gradient = vec3(p.xy * (q.x / (ring * len)), q.y / len);  // unit normal
        float slope = dot(gradient, d);
        if (abs(slope) < 0.05) break;
        t -= (len - r) / slope;
    }
    return t;
}

// The quartic in t whose roots are where the ray o + t d (|d| = 1, torus
// frame) meets the torus: f(o + t d) = t^4 + c3 t^3 + c2 t^2 + c1 t + c0,
// returned as (c3, c2, c1, c0), as solveQuartic takes them.
vec4 torusQuartic(vec3 o, vec3 d, float R, float r)
{
    //@open
    //@ // TODO(05.e): the torus's quartic in t.
    //@ // Put the ray into f(p) above and collect the powers of t
    //@ // (guide, section 5): |d| = 1 makes the t^4 coefficient 1. Name the
    //@ // terms that come back (o . o, o . d, ...) once.
    //@ // Checked by: raylab check --stage 05 (function torusQuartic; views front, torus-closeup).
    //@ labTodo();
    //@ return vec4(0.0, 0.0, 0.0, 1.0);
    //@guided
    float m = dot(o, o);
    float n = dot(o, d);
    float k = m + R * R - r * r;
    float R4 = 4.0 * R * R;
    return vec4(4.0 * n,
                4.0 * n * n + 2.0 * k - R4 * (d.x * d.x + d.y * d.y),
                4.0 * n * k - 2.0 * R4 * (o.x * d.x + o.y * d.y),
                k * k - R4 * (o.x * o.x + o.y * o.y));
    //@end-open
}

// The nearest t > tMin where the ray (in the torus frame, in units where
// 1 <= R < 2) meets the torus, or NO_HIT. (Provided.)
float intersectTorusUnit(Ray ray, float R, float r, float tMin)
{
    // Float precision: the quartic's coefficients grow with the fourth power
    // of the distance to the torus, and the roots drown in rounding error a
    // few radii away (the seed thesis saw exactly this). So first jump to
    // where the ray enters the torus's bounding sphere and solve from there
    // (the numerics tests compare this with the seed's way, which skips
    // this and the Newton steps).
    // A little larger than the torus: on its outer equator the torus touches
    // the sphere R + r, and an entry point rounded inward would start inside.
    float bound = 1.01 * (R + r);
    float b = dot(ray.origin, ray.dir);
    // h = bound^2 - (distance from the centre to the ray's line)^2. Not as
    // b*b - (|o|^2 - bound^2): far away both terms are about |o|^2 and
    // their difference drowns in rounding.
    vec3 closest = ray.origin - b * ray.dir;
    float h = bound * bound - dot(closest, closest);
    if (h < 0.0) return NO_HIT;          // misses the bounding sphere
    if (-b + sqrt(h) <= tMin) return NO_HIT;  // the sphere is behind the ray
    float tEnter = max(-b - sqrt(h), 0.0);
    vec3 o = ray.origin + tEnter * ray.dir;
    vec3 d = ray.dir;

    vec4 roots;
    int count = solveQuartic(torusQuartic(o, d, R, r), roots);
    // Nearest first; each root polished and kept only if the point really
    // lies on the surface (near a double root, rounding can invent a root).
    for (int i = 0; i < count; ++i)
        for (int j = i + 1; j < count; ++j)
            if (roots[j] < roots[i]) { float x = roots[i]; roots[i] = roots[j]; roots[j] = x; }
    for (int i = 0; i < count; ++i) {
        if (tEnter + roots[i] <= tMin) continue;
        float t = polishTorusHit(o, d, roots[i], R, r);
        // Polishing may move a root just in front of the origin behind it.
        if (tEnter + t > tMin && abs(torusDistance(o + t * d, R, r)) < 1e-3 * r) return tEnter + t;
    }
    // No march of the distance function after this for roots the solver
    // might have lost: with the resolvent polished (solve_quartic.glsl) the
    // numerics tests find none lost, grazing rays included, and llvmpipe
    // runs 8 pixels in lock-step through every branch, so even an unused
    // march cost every ray about a tenth of the pro frame (issue 14).
    return NO_HIT;
}

// The same for a torus of any size (in the torus frame): solved in units of
// the power of two just below its major radius, so the quartic's
// coefficients stay near 1 however large or small the torus (in world units
// they grow with R^4 and overflowed float from about R = 1e3 on). A power of
// two, because dividing by it is exact: a torus of any size is solved with
// the same numbers. (Provided.)
float intersectTorusLocal(Ray ray, float R, float r)
{
    float unit = exp2(floor(log2(R)));
    float t = intersectTorusUnit(Ray(ray.origin / unit, ray.dir), R / unit, r / unit, T_MIN / unit);
    return t == NO_HIT ? NO_HIT : t * unit;
}

// The unit outward normal of the torus at a surface point p (torus frame).
// The normal of an implicit surface f(p) = 0 is the direction of the
// gradient of f.
vec3 torusNormalLocal(vec3 p, float R, float r)
{
    //@open
    //@ // TODO(05.d): the torus's normal.
    //@ // The unit outward normal at p, a point on the torus surface:
    //@ // the direction of the gradient of f above.
    //@ // Checked by: raylab check --stage 05 (function torusNormalLocal; views front, torus-closeup).
    //@ labTodo();
    //@ return normalize(p);
    //@guided
    // TODO(05.d): the gradient of f above, divided by 4 for simplicity:
    //     (|p|^2 + R^2 - r^2) p - 2 R^2 (p.x, p.y, 0)
    // normalised.
    // Checked by: raylab check --stage 05 (views front, torus-closeup).
    //@solution
    return normalize((dot(p, p) + R * R - r * r) * p - 2.0 * R * R * vec3(p.xy, 0.0));
    //@stub
    //@ labTodo();
    //@ return normalize(p);
    //@end
    //@end-open
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
