// What shading needs to know about the point a ray hit. Filled in by
// surfaceAt() (surface_at.glsl) for whatever kind of object was hit.
// (Students need not change this file.)
struct Surface {
    vec3 point;         // where the ray hit
    vec3 normal;        // unit normal pointing OUT of the object (not always toward the ray)
    Material material;  // with its texture applied (from stage 06 on)
    vec2 uv;            // texture coordinates (from stage 06 on)
    vec3 tangent;       // unit vector along +u on the surface (from stage 07 on)
};
