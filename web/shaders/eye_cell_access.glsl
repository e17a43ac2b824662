// The web build's eye cells (WebGL 2 has no buffer textures): the same
// function as framework/shaders/variants/eye-cells/08-full/eye_cell_access.glsl,
// over a 2D integer texture filled row by row (texel_rows.glsl).
#include "texel_rows.glsl"
uniform highp isampler2D uEyeCells;  // per cell: (first, count) of its spheres in the tree's items

ivec2 eyeCellList(int cell)
{
    return texelFetch(uEyeCells, dataTexel(cell), 0).xy;
}
