// Real roots of x^4 + a3 x^3 + a2 x^2 + a1 x + a0 = 0, in closed form
// (Ferrari's method). Used for the torus, whose surface meets a line up to
// four times. (Provided: no TODO here, but worth reading.)
//
// 1. Shift x = y - a3/4 to remove the cubic term: y^4 + p y^2 + q y + r = 0.
// 2. Write it as (y^2 + p/2 + m)^2 = 2m y^2 - q y + (m^2 + m p + p^2/4 - r)
//    and choose m > 0 so the right side is a perfect square: m must solve
//    the "resolvent" cubic m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0.
// 3. Then y^2 + p/2 + m = +-(s y - q / (2 s)) with s = sqrt(2 m): two
//    quadratics, up to four roots.
// Floating-point error grows fast with the size of the coefficients, so the
// caller keeps them small (see intersect_torus.glsl); m gets two Newton steps
// on the resolvent and every root two on the original polynomial.

// The largest real root of z^3 + b z^2 + c z + d = 0.
float largestCubicRoot(float b, float c, float d)
{
    // z = w - b/3 gives w^3 + P w + Q = 0.
    float P = c - b * b / 3.0;
    float Q = 2.0 * b * b * b / 27.0 - b * c / 3.0 + d;
    float disc = Q * Q / 4.0 + P * P * P / 27.0;
    float w;
    if (disc > 0.0) {  // one real root (Cardano)
        float sq = sqrt(disc);
        float u = -Q / 2.0 + sq;
        float v = -Q / 2.0 - sq;
        w = sign(u) * pow(abs(u), 1.0 / 3.0) + sign(v) * pow(abs(v), 1.0 / 3.0);
    } else {           // three real roots (trigonometric form); take the largest
        float rho = sqrt(max(-P / 3.0, 0.0));
        float cosAngle = rho > 0.0 ? clamp(-Q / (2.0 * rho * rho * rho), -1.0, 1.0) : 0.0;
        w = 2.0 * rho * cos(acos(cosAngle) / 3.0);
    }
    return w - b / 3.0;
}

float quartic(vec4 a, float x)  // a = (a3, a2, a1, a0)
{
    return (((x + a.x) * x + a.y) * x + a.z) * x + a.w;
}

float quarticSlope(vec4 a, float x)
{
    return ((4.0 * x + 3.0 * a.x) * x + 2.0 * a.y) * x + a.z;
}

// Fills `roots` with the real roots, returns how many (0, 2 or 4).
int solveQuartic(vec4 a, out vec4 roots)
{
    float a3 = a.x, a2 = a.y, a1 = a.z, a0 = a.w;
    float sq3 = a3 * a3;
    float p = a2 - 3.0 * sq3 / 8.0;
    float q = a1 - a2 * a3 / 2.0 + sq3 * a3 / 8.0;
    float r = a0 - a1 * a3 / 4.0 + a2 * sq3 / 16.0 - 3.0 * sq3 * sq3 / 256.0;

    float c1 = p * p / 4.0 - r, c0 = -q * q / 8.0;  // the resolvent's coefficients
    float m = largestCubicRoot(p, c1, c0);
    // Cardano's and the trigonometric formula lose digits near their edge
    // cases, and an m that is a little off loses whole roots of the quartic
    // (deep hits, not grazing ones: the torus's numerics tests found them).
    // Two Newton steps on the cubic bring m back to a few float steps.
    for (int step = 0; step < 2; ++step) {
        float slope = (3.0 * m + 2.0 * p) * m + c1;
        if (abs(slope) > 1e-12) m -= (((m + p) * m + c1) * m + c0) / slope;
    }
    int count = 0;
    roots = vec4(0.0);
    if (m > 1e-7) {
        float s = sqrt(2.0 * m);
        float h = q / (2.0 * s);
        // y^2 - s y + (p/2 + m + h) = 0 and y^2 + s y + (p/2 + m - h) = 0
        float d1 = s * s - 4.0 * (p / 2.0 + m + h);
        float d2 = s * s - 4.0 * (p / 2.0 + m - h);
        if (d1 >= 0.0) {
            float e = sqrt(d1);
            roots[count++] = (s - e) / 2.0;
            roots[count++] = (s + e) / 2.0;
        }
        if (d2 >= 0.0) {
            float e = sqrt(d2);
            roots[count++] = (-s - e) / 2.0;
            roots[count++] = (-s + e) / 2.0;
        }
    } else {
        // q is (almost) 0: y^4 + p y^2 + r = 0 is a quadratic in y^2.
        float d = p * p - 4.0 * r;
        if (d >= 0.0) {
            float e = sqrt(d);
            for (int k = 0; k < 2; ++k) {
                float y2 = (-p + (k == 0 ? -e : e)) / 2.0;
                if (y2 >= 0.0) {
                    roots[count++] = -sqrt(y2);
                    roots[count++] = sqrt(y2);
                }
            }
        }
    }
    for (int i = 0; i < count; ++i) {
        float x = roots[i] - a3 / 4.0;
        for (int step = 0; step < 2; ++step) {  // Newton: x -= f(x) / f'(x)
            float slope = quarticSlope(a, x);
            if (abs(slope) > 1e-12) x -= quartic(a, x) / slope;
        }
        roots[i] = x;
    }
    return count;
}
