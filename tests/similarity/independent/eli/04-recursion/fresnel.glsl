// How much light a smooth surface reflects, by the angle of incidence
// (Schlick's approximation of the Fresnel equations):
//     F(cos) = F0 + (1 - F0) (1 - cos)^5
// F0 is the reflectance looking straight at the surface.

/* Eli: Schlick's angular factor (1 - cos)^5, by repeated squaring instead of
 * pow(). The argument is clamped first: a cosine may round past 1. */
float eliSchlickFactor(float cosTheta)
{
    float oneMinus = clamp(1.0 - cosTheta, 0.0, 1.0);
    float squared = oneMinus * oneMinus;
    return squared * squared * oneMinus;
}

// A dielectric (glass, water) of index of refraction `ior` in air.
// cosOutside: the cosine of the angle between the ray and the normal on the
// AIR side of the boundary. Entering the glass that is the incident ray's
// angle; leaving it, the transmitted ray's. (Schlick is only accurate with
// the angle in the optically thinner medium.)
float fresnelDielectric(float cosOutside, float ior)
{
    /* Normal-incidence reflectance of a dielectric in air. */
    float reflectanceAtZero = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
    return mix(reflectanceAtZero, 1.0, eliSchlickFactor(cosOutside));
}

// A metal (conductor) with complex index of refraction n + ik per colour
// channel: it reflects different colours differently (gold).
vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k)
{
    /* Complex index n + ik: |(N - 1) / (N + 1)|^2, one value per channel. */
    vec3 extinctionSq = k * k;
    vec3 above = n - vec3(1.0);
    vec3 below = n + vec3(1.0);
    vec3 reflectanceAtZero = (above * above + extinctionSq) / (below * below + extinctionSq);
    return mix(reflectanceAtZero, vec3(1.0), eliSchlickFactor(cosIncident));
}

// Glass: a ray with unit direction `dir` meets a glass surface of index of
// refraction `ior`; `normal` is the unit normal facing the ray, and
// `entering` is true when the ray comes from the air. Returns the refracted
// direction in xyz and in w the share F of the light that is reflected (the
// rest goes on in the refracted ray). Under total internal reflection
// nothing is refracted: vec4(0.0, 0.0, 0.0, 1.0).
vec4 refractGlass(vec3 dir, vec3 normal, bool entering, float ior)
{
    /*
     * Snell's law written out by hand (no refract()):
     *   sin^2(out) = (n1/n2)^2 * (1 - cos^2(in)),
     * and sin^2(out) > 1 means total internal reflection.
     */
    float relIndex = ior;                  /* leaving: glass -> air */
    if (entering) {
        relIndex = 1.0 / ior;              /* entering: air -> glass */
    }
    float cosIn = clamp(dot(-dir, normal), 0.0, 1.0);
    float sinOutSq = relIndex * relIndex * (1.0 - cosIn * cosIn);

    vec4 answer = vec4(0.0, 0.0, 0.0, 1.0);   /* total internal reflection */
    if (sinOutSq <= 1.0) {
        float cosOut = sqrt(1.0 - sinOutSq);
        vec3 bent = normalize(relIndex * dir + (relIndex * cosIn - cosOut) * normal);
        /* Schlick must use the angle on the air side of the boundary. */
        float airSideCos = entering ? cosIn : cosOut;
        answer = vec4(bent, fresnelDielectric(airSideCos, ior));
    }
    return answer;
}
