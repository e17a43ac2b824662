// How much light a smooth surface reflects, by the angle of incidence
// (Schlick's approximation of the Fresnel equations):
//     F(cos) = F0 + (1 - F0) (1 - cos)^5
// F0 is the reflectance looking straight at the surface.

// A dielectric (glass, water) of index of refraction `ior` in air.
// cosOutside: the cosine of the angle between the ray and the normal on the
// AIR side of the boundary. Entering the glass that is the incident ray's
// angle; leaving it, the transmitted ray's. (Schlick is only accurate with
// the angle in the optically thinner medium.)
float fresnelDielectric(float cosOutside, float ior)
{
    // TODO(04.c): F0 = ((ior - 1) / (ior + 1))^2, then Schlick.
    // Checked by: raylab check --stage 04 (views front, glass-closeup, inside-glass).
    //@solution
    float f0 = (ior - 1.0) / (ior + 1.0);
    f0 *= f0;
    return f0 + (1.0 - f0) * pow(clamp(1.0 - cosOutside, 0.0, 1.0), 5.0);
    //@stub
    //@ labTodo();
    //@ return 0.5;
    //@end
}

// A metal (conductor) with complex index of refraction n + ik per colour
// channel: it reflects different colours differently (gold).
vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k)
{
    // TODO(04.d): F0 = ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2), per channel,
    // then Schlick with the incident cosine.
    // Checked by: raylab check --stage 04 (view gold).
    //@solution
    vec3 f0 = ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
    return f0 + (1.0 - f0) * pow(clamp(1.0 - cosIncident, 0.0, 1.0), 5.0);
    //@stub
    //@ labTodo();
    //@ return vec3(1.0);
    //@end
}
