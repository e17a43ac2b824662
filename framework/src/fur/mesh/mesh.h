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

// A sphere around every position: the centre of the bounding box and the
// farthest position's distance from it (the near and far planes hug it).
struct BoundingSphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};
BoundingSphere boundingSphere(const Mesh& mesh);

// Area-weighted vertex normals; vertices at one position get one normal
// (smooth across seams). Triangles of zero area add nothing; a vertex that
// touches only such triangles gets (0, 1, 0).
void computeSmoothNormals(Mesh& mesh);

// Texture coordinates for OBJ files without any. A tiling fur pattern needs
// only an even parameterisation; neither projection is even everywhere:
//  - Sphere (the default): around the mesh's centre, smooth everywhere but
//    at its two poles (on the y axis), where the pattern is squeezed into a
//    pinwheel; on a round model they are small, on a long one (a bunny's
//    flank, a teapot's front) they show.
//  - Box (cube): each triangle takes the two coordinates across the axis its
//    face normal is nearest to, in units of kBoxUvSpan: no poles, but a seam
//    wherever neighbouring triangles pick other axes, and the pattern
//    stretched where a face is tilted 45 degrees from its axis. The seams
//    split vertices (adjacency goes by position, so fins do not see them).
// Blending three projections per pixel (triplanar) has neither flaw, but it
// is the fragment shader's work: the students' shell.frag reads the pattern
// at one coordinate, and the course keeps that contract.
enum class UvProjection { Sphere, Box };
inline constexpr float kBoxUvSpan = 4.0f;
void computeBoxUvs(Mesh& mesh);
void computeSphericalUvs(Mesh& mesh);

// Throws Error("NAME: what is wrong") for an empty mesh, indices out of range,
// non-finite values, or attribute lists of the wrong length.
void validateMesh(const Mesh& mesh);

}  // namespace raylab
