// Does light `light` reach `point`? Without shadows, always: lab 03
// replaces this file with one that casts a shadow ray.
bool lightVisible(vec3 point, vec3 normal, int light)
{
    return true;
}
