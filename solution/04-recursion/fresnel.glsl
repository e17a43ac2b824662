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
    //@open
    //@ // TODO(04.c): Fresnel for glass.
    //@ // F for a dielectric of index `ior` (> 1) in air, by Schlick, with F0
    //@ // from the index (guide, section 3). cosOutside is in [0, 1].
    //@ // Checked by: raylab check --stage 04 (function fresnelDielectric; views front, glass-closeup, inside-glass).
    //@ labTodo();
    //@ return 0.5;
    //@guided
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
    //@end-open
}

// A metal (conductor) with complex index of refraction n + ik per colour
// channel: it reflects different colours differently (gold).
vec3 fresnelConductor(float cosIncident, vec3 n, vec3 k)
{
    //@open
    //@ // TODO(04.d): Fresnel for metal.
    //@ // F per colour channel for a metal of complex index n + ik, by
    //@ // Schlick, with F0 from n and k (guide, section 3). cosIncident is in [0, 1].
    //@ // Checked by: raylab check --stage 04 (function fresnelConductor; view gold).
    //@ labTodo();
    //@ return vec3(1.0);
    //@guided
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
    //@end-open
}

// Glass: a ray with unit direction `dir` meets a glass surface of index of
// refraction `ior`; `normal` is the unit normal facing the ray, and
// `entering` is true when the ray comes from the air. Returns the refracted
// direction in xyz and in w the share F of the light that is reflected (the
// rest goes on in the refracted ray). Under total internal reflection
// nothing is refracted: vec4(0.0, 0.0, 0.0, 1.0).
vec4 refractGlass(vec3 dir, vec3 normal, bool entering, float ior)
{
    //@open
    //@ // TODO(04.e): refraction into or out of glass.
    //@ // The refracted direction (unit) and F, as above. Mind which
    //@ // side the ray comes from (`entering`) for the relative index, and which
    //@ // cosine Schlick takes (the one on the air side). GLSL's refract() may
    //@ // help; it returns vec3(0.0) under total internal reflection.
    //@ // Checked by: raylab check --stage 04 (function refractGlass; views glass-closeup, inside-glass).
    //@ labTodo();
    //@ return vec4(0.0, 0.0, 0.0, 1.0);
    //@guided
    // TODO(04.e): the relative index eta is 1/ior entering the glass and ior
    // leaving it. refract(dir, normal, eta) returns vec3(0.0) under total
    // internal reflection: then F = 1. Otherwise F is fresnelDielectric with
    // the cosine on the air side: the incident ray's entering, the refracted
    // ray's leaving.
    // Checked by: raylab check --stage 04 (function refractGlass, views glass-closeup, inside-glass).
    //@solution
    float eta = entering ? 1.0 / ior : ior;
    vec3 refracted = refract(dir, normal, eta);
    if (refracted == vec3(0.0)) return vec4(0.0, 0.0, 0.0, 1.0);  // total internal reflection
    float cosIncident = -dot(dir, normal);
    float cosTransmitted = -dot(refracted, normal);
    return vec4(refracted, fresnelDielectric(entering ? cosIncident : cosTransmitted, ior));
    //@stub
    //@ labTodo();
    //@ return vec4(0.0, 0.0, 0.0, 1.0);  // placeholder: everything reflected
    //@end
    //@end-open
}
