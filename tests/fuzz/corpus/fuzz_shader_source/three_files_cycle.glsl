#version 330 core
#include "a.glsl"
void main() { f(); }
//@@file
#include "b.glsl"
void f() { g(); }
//@@file
#include "a.glsl"
#include "main.glsl"
void g() {}
