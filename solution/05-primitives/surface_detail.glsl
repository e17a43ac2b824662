// Pictures on surfaces: none yet. Lab 06 replaces this file with one that
// applies textures (and lab 07 normal maps).
void addSurfaceDetail(inout Surface s, int kind, int index)
{
}
