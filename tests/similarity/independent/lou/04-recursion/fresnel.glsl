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
    float base = pow((ior - 1.0) / (ior + 1.0), 2.0);
    float oneMinus = max(0.0, min(1.0, 1.0 - cosOutside));
    return base + (1.0 - base) * pow(oneMinus, 5.0);
}

// A metal (conductor) with complex index of refraction n + ik per colour
// channel: it reflects different colours differently (gold).
vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k)
{
    vec3 top = (n - vec3(1.0)) * (n - vec3(1.0)) + k * k;
    vec3 bottom = (n + vec3(1.0)) * (n + vec3(1.0)) + k * k;
    vec3 base = top / bottom;
    float oneMinus = max(0.0, min(1.0, 1.0 - cosIncident));
    return base + (vec3(1.0) - base) * pow(oneMinus, 5.0);
}

// Glass: a ray with unit direction `dir` meets a glass surface of index of
// refraction `ior`; `normal` is the unit normal facing the ray, and
// `entering` is true when the ray comes from the air. Returns the refracted
// direction in xyz and in w the share F of the light that is reflected (the
// rest goes on in the refracted ray). Under total internal reflection
// nothing is refracted: vec4(0.0, 0.0, 0.0, 1.0).
vec4 refractGlass(vec3 dir, vec3 normal, bool entering, float ior)
{
    float eta;
    if (entering) {
        eta = 1.0 / ior;
    } else {
        eta = ior;
    }
    vec3 bent = refract(dir, normal, eta);
    if (bent == vec3(0.0)) {
        return vec4(0.0, 0.0, 0.0, 1.0);
    }
    float cosAir;
    if (entering) {
        cosAir = -dot(dir, normal);
    } else {
        cosAir = -dot(bent, normal);
    }
    return vec4(bent, fresnelDielectric(cosAir, ior));
}
