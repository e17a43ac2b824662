// Colour modes (Up/Down keys), as in the seed thesis: the picture's colour
// channels shuffled. A mode's name says which channel of the traced colour
// feeds red, green and blue of the screen: "BRB" shows blue as red, red as
// green and blue as blue. Mode 0 is the plain picture.
//     0 RGB   1 BRB   2 BRR   3 RBB   4 GGR
uniform int uColorMode;

vec3 applyColorMode(vec3 c)
{
    //@open
    //@ // TODO(08.a): the colour modes.
    //@ // C's channels in the order of mode uColorMode (above); any
    //@ // other mode shows c as it is.
    //@ // Checked by: raylab check --stage 08 (function applyColorMode; views lite-brb, lite-brr, lite-rbb, lite-ggr).
    //@ labTodo();
    //@ return c;
    //@guided
    // TODO(08.a): return the channels in the order of mode uColorMode
    // (GLSL swizzles help: c.brb is vec3(c.b, c.r, c.b)).
    // Checked by: raylab check --stage 08 (function applyColorMode, views lite-brb, lite-brr, lite-rbb, lite-ggr).
    //@solution
    if (uColorMode == 1) return c.brb;
    if (uColorMode == 2) return c.brr;
    if (uColorMode == 3) return c.rbb;
    if (uColorMode == 4) return c.ggr;
    return c;
    //@stub
    //@ labTodo();
    //@ return c;
    //@end
    //@end-open
}
