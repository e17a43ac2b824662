// Where test_spheres.glsl (the eye-cells variant) reads the eye's cells from:
// a buffer texture (framework/src/raytrace/eye_cell_buffers.h). The web
// build, which has no buffer textures, replaces this file with
// web/shaders/eye_cell_access.glsl.
uniform isamplerBuffer uEyeCells;  // per cell: (first, count) of its spheres in the tree's items

ivec2 eyeCellList(int cell)
{
    return texelFetch(uEyeCells, cell).xy;
}
