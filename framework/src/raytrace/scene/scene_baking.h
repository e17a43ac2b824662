#pragma once
// A shader specialised for one scene: the scene's static data - object
// counts, materials, lights, planes, discs, triangles, torus sizes, the sky
// and glow settings - written into the GLSL as constants instead of uniforms.
// Moving data stays uniform (sphere positions, torus axes), and so do the
// run-time switches (shadows, depth, colour mode).
//
// Why: with constants the compiler sees exactly this scene: loops run a fixed
// number of times, kinds the scene lacks (count 0) vanish, arrays shrink to
// the scene's size. The framework/shaders/scene_*.glsl files declare the
// uniforms only when SCENE_BAKED is not defined; the names stay the same, so
// the stage's GLSL is unchanged. `raylab bench` compares both ways.
// (Students need not read this file.)
#include "scene.h"

#include <string>
#include <vector>

namespace raylab {

// The GLSL constants (one declaration per line) for SCENE. With
// SPHERESINSTORAGE the spheres' colours and materials stay in their storage
// blocks (sphere_blocks.h): a scene that needs those has too many spheres
// to spell out.
std::string bakedSceneGlsl(const Scene& scene, bool spheresInStorage = false);

// SCENE_BAKED and MAX_SPHERES, MAX_PLANES, ... set to the scene's own counts
// (at least 1: GLSL has no empty arrays).
std::vector<std::string> bakedSceneDefines(const Scene& scene);

}  // namespace raylab
