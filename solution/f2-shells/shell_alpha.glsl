// How opaque a pixel of a shell is. PATTERN is the fur pattern's value here
// (0: no hair, 1: a tall hair). The skin (layer 0) is opaque; above it a
// shell keeps the hairs, fading out toward the tips, so short hairs end in
// the lower shells and the coat thins out at the top.
#include "lab_todo.glsl"

float shellAlpha(float pattern, float layer)
{
    //@open
    //@ // TODO(f2.c): how opaque a pixel of a shell is.
    //@ // The opacity: the skin is opaque everywhere; above it the
    //@ // hair's PATTERN value, fading linearly to nothing at the tips (guide,
    //@ // section 1).
    //@ // Checked by: raylab check --stage f2 (function shellAlpha; all views).
    //@ labTodo();
    //@ return 1.0;
    //@guided
    // TODO(f2.c): 1 for the skin; else pattern * (1 - layer).
    // Checked by: raylab check --stage f2 (function shellAlpha, all views).
    //@solution
    return layer <= 0.0 ? 1.0 : pattern * (1.0 - layer);
    //@stub
    //@ labTodo();
    //@ return 1.0;
    //@end
    //@end-open
}
