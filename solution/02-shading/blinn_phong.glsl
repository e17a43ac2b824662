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
    //@open
    //@ // TODO(02.a): the Blinn-Phong colour of the point.
    //@ // That is the material's ambient colour once, plus for every light i < uLightCount
    //@ // that reaches the point (ask lightVisible(point, normal, i): it says yes
    //@ // to every light until lab 03) its diffuse and its specular term
    //@ // (guide, sections 2 and 3): light i is at uLightPositions[i]
    //@ // with colour uLightColors[i]; `normal` and `toEye` are unit vectors, the
    //@ // normal on the eye's side. No specular highlight where the light is
    //@ // behind the surface.
    //@ // Checked by: raylab check --stage 02 (function blinnPhong; views front, dark-side, highlights, inside).
    //@ labTodo();
    //@ return m.diffuse;
    //@guided
    vec3 color = vec3(0.0);

    // TODO(02.a): the ambient colour, added once: it stands for light that
    // arrives from everywhere, not from one lamp.
    // Checked by: raylab check --stage 02 (function blinnPhong, views dark-side, inside).
    //@solution
    color += m.ambient;
    //@stub
    //@ labTodo();
    //@end

    for (int i = 0; i < uLightCount; ++i) {
        if (!lightVisible(point, normal, i)) continue;  // blocked: in shadow (from lab 03 on)
        vec3 toLight = normalize(uLightPositions[i] - point);

        // TODO(02.b): the diffuse term of light i,
        //     uLightColors[i] * m.diffuse * max(N . L, 0)
        // with L = toLight.
        // Checked by: raylab check --stage 02 (function blinnPhong, views front, dark-side).
        //@solution
        float lambert = max(dot(normal, toLight), 0.0);
        color += uLightColors[i] * m.diffuse * lambert;
        //@stub
        //@ labTodo();
        //@ color += m.diffuse / float(uLightCount);  // placeholder: the flat colour of lab 01
        //@end

        // TODO(02.c): the specular term of light i,
        //     uLightColors[i] * m.specular * max(N . H, 0)^m.shininess
        // with H the unit half vector between L and toEye - only where the
        // light reaches the front of the surface (N . L > 0).
        // Checked by: raylab check --stage 02 (function blinnPhong, view highlights).
        //@solution
        if (lambert > 0.0) {
            vec3 halfway = normalize(toLight + toEye);
            color += uLightColors[i] * m.specular * pow(max(dot(normal, halfway), 0.0), m.shininess);
        }
        //@stub
        //@ labTodo();
        //@end
    }
    return color;
    //@end-open
}
