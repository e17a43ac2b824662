#pragma once
// The scenes of `raylab bench --growth` (cmd_bench_growth.cpp), made in
// code: one fixed view, a floor and one light, and either one sphere mesh
// or a cloud of spheres. Also the starting point of tests that need a scene
// of many objects (tests/e2e/sphere_blocks_test.cpp).
#include "scene.h"

#include <string>

namespace raylab {

// The fixed part: camera, floor (material 1), light, a clay material (0).
Scene growthBaseScene(const std::string& name);

// A sphere mesh with the most triangles (4d^2 - 4d) not above WANTED.
Scene growthMeshScene(long wanted);

// N spheres of material 0 on a jittered grid filling the box [-1, 1]^3
// (deterministic), in index order: x fastest, then y, then z.
Scene growthSphereScene(int n);

}  // namespace raylab
