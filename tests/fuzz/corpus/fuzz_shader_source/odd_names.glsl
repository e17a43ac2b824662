#include "sub/dir/x.glsl"
#include "."
#include "a.glsl/"
