// How far a vertex of a shell moves off the skin: along the surface's
// normal, a share LAYER of the fur's length (the seed's
// `offset = layer * length * normalize(normal)`).
#include "lab_todo.glsl"

vec3 shellOffset(vec3 normal, float layer, float furLength)
{
    return layer * furLength * normalize(normal);
}
