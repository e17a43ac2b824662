#include "a.glsl"
#include "a.glsl"
#include "missing.glsl"
//@@file
#version 100
float a;
