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

    color += m.ambient;

    for (int i = 0; i < uLightCount; ++i) {
        if (!lightVisible(point, normal, i)) continue;  // blocked: in shadow (from lab 03 on)
        vec3 toLight = normalize(uLightPositions[i] - point);

        float lambert = max(dot(normal, toLight), 0.0);
        color += uLightColors[i] * m.diffuse * lambert;

        if (lambert > 0.0) {
            vec3 halfway = normalize(toLight + toEye);
            color += uLightColors[i] * m.specular * pow(max(dot(normal, halfway), 0.0), m.shininess);
        }
    }
    return color;
}
