#pragma once
// Edges with their neighbours, for a geometry shader that takes
// GL_LINES_ADJACENCY: four indices per edge, A B C D, where B-C is the edge,
// A the third corner of one triangle (A, B, C counter-clockwise from
// outside) and D the third corner of the triangle on the other side.
//
// Neighbours are found by position, not by index, so seams (vertices
// repeated with other texture coordinates or normals) do not cut the mesh.
// The awkward cases, each with one rule the fin shader and the CPU count
// (silhouette.h) share:
//   - a boundary edge (one triangle) gets D = A: the second normal is then
//     the first one reversed, so the edge counts as a silhouette from every
//     side - the rim of an open surface shows its fur;
//   - a non-manifold edge (three or more triangles) is split into pairs of
//     triangles that run along it in opposite directions (consistently
//     oriented neighbours); whatever is left over is treated as boundary;
//   - a degenerate triangle (zero area, or two corners at one position) has
//     no normal and no silhouette: it is left out, and its neighbours see a
//     boundary there.
#include "mesh.h"

#include <cstdint>
#include <vector>

namespace raylab {

struct EdgeAdjacency {
    std::vector<std::uint32_t> indices;  // 4 per edge: A, B, C, D
    long interiorEdges = 0;              // two triangles
    long boundaryEdges = 0;              // one triangle, and non-manifold leftovers
    long nonManifoldEdges = 0;           // edges with three or more triangles
    long degenerateTriangles = 0;        // left out
    std::size_t edgeCount() const { return indices.size() / 4; }
};

EdgeAdjacency buildEdgeAdjacency(const Mesh& mesh);

}  // namespace raylab
