// The web build's light buffer storage (WebGL 2 has no buffer textures): the
// same two functions as framework/shaders/variants/light-buffer/08-full/
// light_buffer_access.glsl, over 2D integer textures filled row by row
// (texel_rows.glsl).
#include "texel_rows.glsl"
uniform highp isampler2D uLightCells;  // per cell: (first, count) of its spheres, of its triangles
uniform highp isampler2D uLightItems;  // the lists: sphere and triangle indices

ivec4 lightCellList(int cell)
{
    return texelFetch(uLightCells, dataTexel(cell), 0);
}

int lightItem(int k)
{
    return texelFetch(uLightItems, dataTexel(k), 0).r;
}
