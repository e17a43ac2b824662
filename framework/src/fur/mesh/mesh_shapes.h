#pragma once
// The procedural meshes of the fur track: a sphere, a torus and a cube, each
// at any tessellation, so that the bench can draw the same shape from about
// a hundred to a few hundred thousand triangles.
#include "mesh.h"

#include <string>
#include <vector>

namespace raylab {

// DETAIL sets the tessellation (at least 2 for the sphere and torus, 1 for
// the cube):
//   sphere: 2*DETAIL slices, DETAIL stacks, 4*DETAIL^2 - 4*DETAIL triangles,
//           radius 1; the poles are fans, so no triangle is degenerate;
//   torus:  ring radius 1, tube radius 0.4, 4*DETAIL^2 triangles;
//   cube:   side 2, each face a DETAIL x DETAIL grid, 12*DETAIL^2 triangles,
//           one normal per face (sharp edges: shells part there, fins fill in).
// Every shape has a texture seam, where vertices repeat with other texture
// coordinates. Throws Error for an unknown shape or a detail out of range.
Mesh makeShape(const std::string& shape, int detail);

// The shapes makeShape knows, for messages and the window's mesh key.
const std::vector<std::string>& shapeNames();

// The tessellation the demo scenes use for SHAPE (a few thousand triangles).
int defaultDetail(const std::string& shape);

// The detail that gives SHAPE about TRIANGLES triangles (the bench's series).
int detailForTriangles(const std::string& shape, long triangles);

}  // namespace raylab
