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
    labTodo();
    return 0.5;
}

// A metal (conductor) with complex index of refraction n + ik per colour
// channel: it reflects different colours differently (gold).
vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k)
{
    // TODO(04.d): F0 = ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2), per channel,
    // then Schlick with the incident cosine.
    // Checked by: raylab check --stage 04 (view gold).
    labTodo();
    return vec3(1.0);
}
