// Normal maps: not yet. Lab 07 replaces this file with one that tilts the
// normal by the material's normal map.
void applyNormalMap(inout Surface s)
{
}
