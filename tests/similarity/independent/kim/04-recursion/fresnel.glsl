// How much light a smooth surface reflects, by the angle of incidence
// (Schlick's approximation of the Fresnel equations):
//     F(cos) = F0 + (1 - F0) (1 - cos)^5
// F0 is the reflectance looking straight at the surface.

// A dielectric (glass, water) of index of refraction `ior` in air.
// cosOutside: the cosine of the angle between the ray and the normal on the
// AIR side of the boundary. Entering the glass that is the incident ray's
// angle; leaving it, the transmitted ray's. (Schlick is only accurate with
// the angle in the optically thinner medium.)
float schlick(float r0, float c)
{
    float m = clamp(1.0 - c, 0.0, 1.0);
    float m2 = m * m;
    return r0 + (1.0 - r0) * m2 * m2 * m;
}

float fresnelDielectric(float cosOutside, float ior)
{
    float r = (ior - 1.0) / (ior + 1.0);
    return schlick(r * r, cosOutside);
}

// A metal (conductor) with complex index of refraction n + ik per colour
// channel: it reflects different colours differently (gold).
vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k)
{
    vec3 k2 = k * k;
    vec3 r0 = ((n - 1.0) * (n - 1.0) + k2) / ((n + 1.0) * (n + 1.0) + k2);
    return vec3(schlick(r0.r, cosIncident), schlick(r0.g, cosIncident), schlick(r0.b, cosIncident));
}

// Glass: a ray with unit direction `dir` meets a glass surface of index of
// refraction `ior`; `normal` is the unit normal facing the ray, and
// `entering` is true when the ray comes from the air. Returns the refracted
// direction in xyz and in w the share F of the light that is reflected (the
// rest goes on in the refracted ray). Under total internal reflection
// nothing is refracted: vec4(0.0, 0.0, 0.0, 1.0).
vec4 refractGlass(vec3 dir, vec3 normal, bool entering, float ior)
{
    vec3 t = refract(dir, normal, entering ? 1.0 / ior : ior);
    if (dot(t, t) == 0.0) return vec4(0.0, 0.0, 0.0, 1.0);
    float c = entering ? dot(-dir, normal) : dot(-t, normal);
    return vec4(t, fresnelDielectric(c, ior));
}
