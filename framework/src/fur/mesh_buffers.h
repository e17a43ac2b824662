#pragma once
// A mesh on the GPU: one vertex buffer (position, normal, texture
// coordinate at attribute locations 0, 1, 2) read through two index
// buffers - the triangles, and the edges with their neighbours for
// GL_LINES_ADJACENCY (adjacency.h) when the stage draws fins.
#include "adjacency.h"
#include "gl.h"
#include "mesh.h"

namespace raylab {

class MeshBuffers {
public:
    // ADJACENCY may be null (no fins).
    MeshBuffers(const Mesh& mesh, const EdgeAdjacency* adjacency);
    ~MeshBuffers();
    MeshBuffers(const MeshBuffers&) = delete;
    MeshBuffers& operator=(const MeshBuffers&) = delete;

    void drawTriangles() const;
    void drawEdgesWithAdjacency() const;  // no-op without adjacency
    // Bytes held on the GPU: vertices, triangle indices, adjacency indices.
    std::size_t bytes() const { return bytes_; }
    std::size_t adjacencyBytes() const {
        return std::size_t(edgeIndexCount_) * sizeof(std::uint32_t);
    }

private:
    GLuint vertices_ = 0, triangles_ = 0, edges_ = 0;
    GLuint triangleVao_ = 0, edgeVao_ = 0;
    GLsizei triangleIndexCount_ = 0, edgeIndexCount_ = 0;
    std::size_t bytes_ = 0;
};

}  // namespace raylab
