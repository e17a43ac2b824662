// Variant of solution/02-shading/blinn_phong.glsl, used instead of it when
// RAYLAB_SHARED_WORK is defined (the demo, and raylab bench's "shared"
// lever). Not part of any lab: students never see this file.
//
// The same shading, except that the loop over the lights visits only those
// in front of the surface (see below). Same picture.
//
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

    // The lights in front of the surface first, packed into a list: the
    // loop below then runs as often as the pixel with the most of them
    // needs (of the 8 that llvmpipe runs together), and no pixel spends a
    // turn on a light behind its surface, which adds nothing.
    // The list is a mask of bits, one a light, not an array: a write to an
    // array at an index that differs between the 8 pixels is 8 stores on
    // llvmpipe, a read 8 loads. The lights still come in index order.
    int lit = 0;
    for (int i = 0; i < uLightCount; ++i)
        if (dot(normal, uLightPositions[i] - point) > 0.0) lit |= 1 << i;
    while (lit != 0) {
        int lowest = lit & -lit;
        lit -= lowest;
        int i = int(log2(float(lowest)));  // exact: a power of two
        if (!lightVisible(point, normal, i)) continue;  // blocked: in shadow
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
