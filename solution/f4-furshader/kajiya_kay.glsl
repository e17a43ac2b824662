// Kajiya and Kay's lighting of a hair: a thin cylinder has no single normal,
// only a direction (the tangent T). Seen from the light, it is lit in
// proportion to sin(T, L), the width it shows the light; its highlight is a
// cone of reflected light around T, brightest when the eye is on it:
//     diffuse  = sin(T, L)
//     specular = max(0, sin(T, L) sin(T, E) - (T . L)(T . E)) ^ shininess
// where sin(T, X) = sqrt(1 - (T . X)^2) and L, E point toward the light and
// the eye. Returns (diffuse, specular).
#include "lab_todo.glsl"

vec2 kajiyaKay(vec3 tangent, vec3 toLight, vec3 toEye, float shininess)
{
    //@open
    //@ // TODO(f4.b): Kajiya and Kay's two terms.
    //@ // (diffuse, specular) above for the unit vectors TANGENT,
    //@ // TOLIGHT and TOEYE. No NaN may reach the picture, whatever rounding does
    //@ // to the dot products (guide, section 4).
    //@ // Checked by: raylab check --stage f4 (function kajiyaKay; view "fur-shader").
    //@ labTodo();
    //@ return vec2(1.0, 0.0);
    //@guided
    // TODO(f4.b): return (diffuse, specular) for the unit vectors above.
    // Rounding can make (T . L)^2 a hair above 1: clamp what goes into
    // sqrt() and pow() at 0, or a NaN reaches the picture.
    // Checked by: raylab check --stage f4 (function kajiyaKay, view "fur-shader").
    //@solution
    float tl = dot(tangent, toLight);
    float te = dot(tangent, toEye);
    float sinTl = sqrt(max(0.0, 1.0 - tl * tl));
    float sinTe = sqrt(max(0.0, 1.0 - te * te));
    return vec2(sinTl, pow(max(0.0, sinTl * sinTe - tl * te), shininess));
    //@stub
    //@ labTodo();
    //@ return vec2(1.0, 0.0);
    //@end
    //@end-open
}
