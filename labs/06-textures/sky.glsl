// The colour of a ray that hits nothing: the sky box when the scene has one,
// else the background colour.
//
// A sky box is a cube around the world whose six inside faces show the
// distant sky. It is so far away that only the ray's direction matters, not
// where it starts - which is exactly what a cube map looks up: the GPU picks
// the face the direction points at, and the spot on it.
vec3 skyColor(vec3 dir)
{
    if (uHasSky == 0) return uBackground;
    // TODO(06.c): look the direction up in the cube map uSky (level 0, as
    // for every texture in the tracer: textureLod(uSky, dir, 0.0)).
    // Checked by: raylab check --stage 06 (function skyColor; views front, sky-up).
    labTodo();
    return uBackground;
}
