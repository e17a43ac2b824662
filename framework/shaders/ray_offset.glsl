// Where a secondary ray (shadow, reflected, refracted) starts: a hit point
// moved off its surface, so that the new ray does not hit the surface it
// leaves from ("acne"). (Students need not change this file; labs 03 and 04
// call it.)
//
// A hit point computed in float lies a little above or below the true
// surface, and "a little" grows with the size of the coordinates: float
// numbers are spaced 1.2e-7 apart near 1, 1e-3 apart near 10^4 and 0.06 near
// 10^6. A fixed offset such as 1e-3 is therefore far too large in a small
// scene and too small in a big one (from about 10^4 units on, acne returns;
// tests/numerics/offset_test.cpp measures it).
//
// So the offset is measured in float steps of the point itself (Waechter and
// Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray
// Tracing Gems, chapter 6, 2019): each coordinate moves by up to
// RAY_OFFSET_INT_SCALE steps of its own spacing, in proportion to the
// normal's component along it - adding an integer to a float's bit pattern
// moves it by that many representable numbers. Near zero, where the spacing
// becomes tiny, a small fixed offset takes over.
//
// n points to the side the new ray leaves from: the surface normal for a ray
// that leaves on the normal's side, -normal for one that goes through.
// Compiling with RAYLAB_NAIVE_NUMERICS defined gives the old fixed offset
// instead (for the numerics tests and the benchmark).

const float RAY_OFFSET_INT_SCALE = 256.0;           // float steps along a unit normal component
const float RAY_OFFSET_FLOAT_SCALE = 1.0 / 65536.0; // the fixed offset near the origin
const float RAY_OFFSET_ORIGIN = 1.0 / 32.0;         // |coordinate| below this counts as near the origin
const float RAY_OFFSET_NAIVE = 1e-3;                // the old fixed offset (RAYLAB_NAIVE_NUMERICS)

// One coordinate p moved by `steps` float steps away from zero (steps < 0:
// toward zero); the bit patterns of floats of one sign are ordered like the
// numbers, so integer addition walks from one float to the next.
float offsetCoordinate(float p, float n, int steps)
{
    if (abs(p) < RAY_OFFSET_ORIGIN) return p + RAY_OFFSET_FLOAT_SCALE * n;
    return intBitsToFloat(floatBitsToInt(p) + (p < 0.0 ? -steps : steps));
}

vec3 offsetRayOrigin(vec3 p, vec3 n)
{
#ifdef RAYLAB_NAIVE_NUMERICS
    return p + n * RAY_OFFSET_NAIVE;
#else
    ivec3 steps = ivec3(RAY_OFFSET_INT_SCALE * n);
    return vec3(offsetCoordinate(p.x, n.x, steps.x), offsetCoordinate(p.y, n.y, steps.y), offsetCoordinate(p.z, n.z, steps.z));
#endif
}
