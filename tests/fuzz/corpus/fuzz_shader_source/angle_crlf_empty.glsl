  #  include <a.glsl> // angle brackets
#include ""
//@@file
int x;
