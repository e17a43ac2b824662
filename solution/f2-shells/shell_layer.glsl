// Which layer of the fur one draw call of the shell program draws.
//
// The framework draws the mesh SHELLCOUNT times per frame, calling this
// with DRAWINDEX = 0, 1, ..., SHELLCOUNT - 1 in that order. Layer 0 is the
// skin, layer 1 the tips of the hairs. Shells are see-through and are
// blended over what is already drawn, so the order is the picture: the
// skin first, then outwards, each shell over the ones below it (guide,
// section 2, "Why the order matters").
#include "lab_todo.glsl"

float shellLayer(int drawIndex, int shellCount)
{
    //@open
    //@ // TODO(f2.a): which layer a draw is.
    //@ // The layer of draw DRAWINDEX of SHELLCOUNT, in the order the
    //@ // picture needs (guide, section 2), the layers evenly spaced from the skin
    //@ // (0) to the tips (1). With one shell there is only the skin.
    //@ // Checked by: raylab check --stage f2 (function shellLayer; all views).
    //@ labTodo();
    //@ return 0.0;
    //@guided
    // TODO(f2.a): return the layer of draw DRAWINDEX: 0 for the first draw,
    // 1 for the last, evenly spaced between. With one shell, only the skin.
    // Checked by: raylab check --stage f2 (function shellLayer, all views).
    //@solution
    return shellCount > 1 ? float(drawIndex) / float(shellCount - 1) : 0.0;
    //@stub
    //@ labTodo();
    //@ return 0.0;
    //@end
    //@end-open
}
