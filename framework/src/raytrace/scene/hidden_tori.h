#pragma once
// Tori that no shadow ray can decide: each inside a closed convex shell of
// the scene file's triangles (pro's glass cube around its gold torus), with
// every light outside that shell. A shadow ray is a segment from a surface
// point to a light outside the shell; if it meets the torus it also crosses
// the shell - leaving it, or entering it on the way - and shadow rays stop
// at any object in between, glass included. The triangle test is watertight
// (intersect_triangle.glsl: no ray slips between two triangles of the
// shell), so the shell's answer is always there first, and the light
// buffer's shadow rays skip the tori (RAYLAB_TORI_HIDDEN_FROM_LIGHTS,
// variants/light-buffer/08-full/light_buffer.glsl). On llvmpipe, which runs
// a loop's body at least once, only a torus test left out of the program
// costs nothing: in pro the three shadow rays' torus tests were 16 M of a
// frame's 209 M instructions, and never changed one answer.
// (Students need not read this file.)
#include "scene.h"

namespace raylab {

// True when SCENE has tori and every one of them is hidden from every light
// as above, with room to spare (a thousandth of the shell's size, and more
// than the tracer's T_MIN, between the torus's ball and the shell, and
// between a light and the shell's nearest face plane it lies outside of).
bool toriHiddenFromLights(const Scene& scene);

}  // namespace raylab
