// The colour of a ray that hits nothing: the scene's background. Lab 06
// replaces it with a sky box.
vec3 skyColor(vec3 dir)
{
    return uBackground;
}
