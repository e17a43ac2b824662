// Blinn-Phong shading of one surface point.
//   point   - the surface point
//   normal  - unit surface normal, facing the eye
//   toEye   - unit vector from the point toward the eye
//   m       - the surface's material
// Returns ambient + sum over the lights of (diffuse + specular).
vec3 blinnPhong(vec3 point, vec3 normal, vec3 toEye, Material m)
{
    vec3 color = vec3(0.0);

    // TODO(02.a): ambient and diffuse. Add the ambient colour once (it
    // stands for light that arrives from everywhere, not from one lamp),
    // then for every light i < uLightCount the diffuse term
    //     lightColor * m.diffuse * max(N . L, 0)
    // with L the unit vector from the point toward the light.
    // Checked by: raylab check --stage 02 (views front, dark-side, inside).
    labTodo();
    color = m.diffuse;  // placeholder: the flat colour of lab 01

    // TODO(02.b): specular highlights. For every light add
    //     lightColor * m.specular * max(N . H, 0)^m.shininess
    // with H the unit half vector between L and toEye - but only where the
    // light reaches the front of the surface (N . L > 0).
    // Checked by: raylab check --stage 02 (views front, highlights).
    labTodo();
    return color;
}
