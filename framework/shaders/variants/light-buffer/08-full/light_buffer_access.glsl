// Where light_buffer.glsl reads the light buffer from: two buffer textures
// (framework/src/raytrace/light_buffer_buffers.h). The web build, which has
// no buffer textures, replaces this file with web/shaders/light_buffer_access.glsl.
uniform isamplerBuffer uLightCells;  // per cell: (first, count) of its spheres, of its triangles
uniform isamplerBuffer uLightItems;  // the lists: sphere and triangle indices

ivec4 lightCellList(int cell)
{
    return texelFetch(uLightCells, cell);
}

int lightItem(int k)
{
    return texelFetch(uLightItems, k).r;
}
