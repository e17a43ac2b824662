// Fur is darker at its roots, where the hairs above shade it: the colour is
// scaled by 1 - intensity * (1 - layer) - by 1 - intensity at the skin and
// by 1 at the tips.
#include "lab_todo.glsl"

float shellShadow(float layer, float intensity)
{
    //@open
    //@ // TODO(f2.d): the factor above.
    //@ // Checked by: raylab check --stage f2 (function shellShadow; all views).
    //@ labTodo();
    //@ return 1.0;
    //@guided
    // TODO(f2.d): return the factor above.
    // Checked by: raylab check --stage f2 (function shellShadow, all views).
    //@solution
    return 1.0 - intensity * (1.0 - layer);
    //@stub
    //@ labTodo();
    //@ return 1.0;
    //@end
    //@end-open
}
