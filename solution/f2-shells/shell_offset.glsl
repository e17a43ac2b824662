// How far a vertex of a shell moves off the skin: along the surface's
// normal, a share LAYER of the fur's length (the seed's
// `offset = layer * length * normalize(normal)`).
#include "lab_todo.glsl"

vec3 shellOffset(vec3 normal, float layer, float furLength)
{
    //@open
    //@ // TODO(f2.b): how far a shell lies off the skin.
    //@ // The offset above. NORMAL may not be unit length; the offset's
    //@ // length is LAYER * FURLENGTH whatever NORMAL's.
    //@ // Checked by: raylab check --stage f2 (function shellOffset; all views).
    //@ labTodo();
    //@ return vec3(0.0);
    //@guided
    // TODO(f2.b): return the offset. NORMAL may not be unit length.
    // Checked by: raylab check --stage f2 (function shellOffset, all views).
    //@solution
    return layer * furLength * normalize(normal);
    //@stub
    //@ labTodo();
    //@ return vec3(0.0);
    //@end
    //@end-open
}
