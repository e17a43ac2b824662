// Blinn-Phong shading of one surface point.
//   point   - the surface point
//   normal  - unit surface normal, facing the eye
//   toEye   - unit vector from the point toward the eye
//   m       - the surface's material
// Returns ambient + sum over the lights that reach the point of
// (diffuse + specular).
#include "light_visibility.glsl"

vec3 blinnPhong(vec3 point, vec3 normal, vec3 toEye, Material m)
{
    vec3 color = vec3(0.0);

    // TODO(02.a): the ambient colour, added once: it stands for light that
    // arrives from everywhere, not from one lamp.
    // Checked by: raylab check --stage 02 (function blinnPhong, views dark-side, inside).
    labTodo();

    for (int i = 0; i < uLightCount; ++i) {
        if (!lightVisible(point, normal, i)) continue;  // blocked: in shadow (from lab 03 on)
        vec3 toLight = normalize(uLightPositions[i] - point);

        // TODO(02.b): the diffuse term of light i,
        //     uLightColors[i] * m.diffuse * max(N . L, 0)
        // with L = toLight.
        // Checked by: raylab check --stage 02 (function blinnPhong, views front, dark-side).
        labTodo();
        color += m.diffuse / float(uLightCount);  // placeholder: the flat colour of lab 01

        // TODO(02.c): the specular term of light i,
        //     uLightColors[i] * m.specular * max(N . H, 0)^m.shininess
        // with H the unit half vector between L and toEye - only where the
        // light reaches the front of the surface (N . L > 0).
        // Checked by: raylab check --stage 02 (function blinnPhong, view highlights).
        labTodo();
    }
    return color;
}
