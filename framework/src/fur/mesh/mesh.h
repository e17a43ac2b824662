#pragma once
// A triangle mesh as the fur track draws it: one list of vertices (position,
// normal, texture coordinate) and three indices per triangle, counter-
// clockwise seen from outside. Vertices that share a position but not a
// normal or texture coordinate (a seam, a cube's corner) are separate
// vertices; edge adjacency (adjacency.h) finds neighbours by position.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

struct Mesh {
    std::string name;  // "sphere-2k", "bunny.obj": for messages and the bench
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // unit length, one per position
    std::vector<glm::vec2> uvs;      // one per position
    std::vector<std::uint32_t> indices;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    // Bytes of the vertex and index buffers the GPU holds for this mesh.
    std::size_t bufferBytes() const;
};

// Area-weighted vertex normals; vertices at one position get one normal
// (smooth across seams). Triangles of zero area add nothing; a vertex that
// touches only such triangles gets (0, 1, 0).
void computeSmoothNormals(Mesh& mesh);

// Texture coordinates by spherical projection around the mesh's centre (for
// OBJ files without any): a tiling fur pattern needs only a continuous,
// roughly even parameterisation.
void computeSphericalUvs(Mesh& mesh);

// Throws Error("NAME: what is wrong") for an empty mesh, indices out of range,
// non-finite values, or attribute lists of the wrong length.
void validateMesh(const Mesh& mesh);

}  // namespace raylab
