// Texture coordinates on a sphere, like longitude and latitude on a globe.
//
// d is the unit vector from the sphere's centre to the surface point.
//     longitude phi = atan(-d.z, d.x)   in (-pi, pi], growing eastward
//     latitude theta = asin(d.y)        in [-pi/2, pi/2], +pi/2 at the north pole
//     u = 0.5 + phi / (2 pi),   v = 0.5 + theta / pi
// so the whole picture (u and v in [0, 1]) wraps around the sphere once,
// with its top row at the north pole (+y). The minus in atan(-d.z, d.x)
// keeps the picture from being mirrored when seen from outside.
const float PI = 3.14159265358979;

vec2 sphereUV(vec3 d)
{
    //@open
    //@ // TODO(06.a): texture coordinates on a sphere.
    //@ // (u, v) of the unit direction d, as defined above, both in
    //@ // [0, 1]; d.y may round to just beyond 1 at a pole.
    //@ // Checked by: raylab check --stage 06 (function sphereUV; views front, earth-closeup, moon-closeup).
    //@ labTodo();
    //@ return vec2(0.0);
    //@guided
    // TODO(06.a): u and v as above. GLSL's two-argument atan(y, x) is
    // atan2: it returns the angle in (-pi, pi] of the point (x, y).
    // Checked by: raylab check --stage 06 (function sphereUV, views front, earth-closeup, moon-closeup).
    //@solution
    float phi = atan(-d.z, d.x);
    float theta = asin(clamp(d.y, -1.0, 1.0));
    return vec2(0.5 + phi / (2.0 * PI), 0.5 + theta / PI);
    //@stub
    //@ labTodo();
    //@ return vec2(0.0);
    //@end
    //@end-open
}

// The direction of growing u (east) at d: the derivative of the point with
// respect to phi, normalised. Used by normal mapping (lab 07). At the poles
// east is undefined; any direction along the surface will do there.
vec3 sphereTangent(vec3 d)
{
    vec3 east = vec3(d.z, 0.0, -d.x);
    float len = length(east);
    return len > 1e-6 ? east / len : vec3(1.0, 0.0, 0.0);
}
