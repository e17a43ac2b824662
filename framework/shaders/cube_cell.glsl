// The cell of a cube of cells around a point that direction d (from the
// point, any length > 0) falls in: the face of d's largest component, then a
// square grid of `size` x `size` cells on that face; cells numbered face by
// face, row by row. Used by the light buffer and the eye's cells (variants
// light-buffer and eye-cells; framework/src/raytrace/scene/cell_cube.h
// computes the same in C++). (Students need not read this file.)
// Selects, not branches: llvmpipe would run every branch for all 8 pixels.
int cubeCell(vec3 d, int size)
{
    vec3 a = abs(d);
    bool xMajor = a.x >= a.y && a.x >= a.z, yMajor = !xMajor && a.y >= a.z;
    float major = xMajor ? d.x : yMajor ? d.y : d.z;
    vec2 uv = (xMajor ? d.yz : yMajor ? d.xz : d.xy) / abs(major);
    int face = 2 * (xMajor ? 0 : yMajor ? 1 : 2) + (major < 0.0 ? 1 : 0);
    ivec2 c = clamp(ivec2(floor((uv * 0.5 + 0.5) * float(size))), ivec2(0), ivec2(size - 1));
    return (face * size + c.y) * size + c.x;
}
