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
    // f0 from the index, then schlick; 1 - cos clamped so pow never sees < 0
    float r0 = (ior - 1.0) / (ior + 1.0);
    r0 *= r0;
    float x = clamp(1.0 - cosOutside, 0.0, 1.0);
    return r0 + (1.0 - r0) * pow(x, 5.0);
}

// A metal (conductor) with complex index of refraction n + ik per colour
// channel: it reflects different colours differently (gold).
vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k)
{
    // per channel: f0 = ((n-1)^2 + k^2) / ((n+1)^2 + k^2)
    vec3 k2 = k * k;
    vec3 f0 = ((n - 1.0) * (n - 1.0) + k2) / ((n + 1.0) * (n + 1.0) + k2);
    float x = clamp(1.0 - cosIncident, 0.0, 1.0);
    return f0 + (1.0 - f0) * pow(x, 5.0);
}

// Glass: a ray with unit direction `dir` meets a glass surface of index of
// refraction `ior`; `normal` is the unit normal facing the ray, and
// `entering` is true when the ray comes from the air. Returns the refracted
// direction in xyz and in w the share F of the light that is reflected (the
// rest goes on in the refracted ray). Under total internal reflection
// nothing is refracted: vec4(0.0, 0.0, 0.0, 1.0).
vec4 refractGlass(vec3 dir, vec3 normal, bool entering, float ior)
{
    // eta = n1 / n2: air->glass 1/ior, glass->air ior
    float eta = entering ? 1.0 / ior : ior;
    vec3 t = refract(dir, normal, eta);
    if (dot(t, t) == 0.0) return vec4(0.0, 0.0, 0.0, 1.0);   // total internal reflection
    t = normalize(t);
    // schlick wants the cosine on the air side: incident going in, transmitted going out
    float c = entering ? -dot(dir, normal) : -dot(t, normal);
    return vec4(t, fresnelDielectric(c, ior));
}
