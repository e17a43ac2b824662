#include "mesh_buffers.h"

#include <cstddef>
#include <vector>

namespace raylab {

namespace {

struct Vertex {
    glm::vec3 position, normal;
    glm::vec2 uv;
};

// Attribute locations, as the vertex shaders declare them (layout(location = N)).
void describeVertex(GLuint vao, GLuint vertices) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vertices);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, uv)));
}

GLuint indexBuffer(const std::vector<std::uint32_t>& indices) {
    GLuint id = 0;
    glGenBuffers(1, &id);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, id);  // recorded in the bound VAO
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)),
                 indices.data(), GL_STATIC_DRAW);
    return id;
}

}  // namespace

MeshBuffers::MeshBuffers(const Mesh& mesh, const EdgeAdjacency* adjacency) {
    std::vector<Vertex> vertices(mesh.vertexCount());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {mesh.positions[i], mesh.normals[i], mesh.uvs[i]};
    glGenBuffers(1, &vertices_);
    glBindBuffer(GL_ARRAY_BUFFER, vertices_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
                 GL_STATIC_DRAW);
    bytes_ = vertices.size() * sizeof(Vertex);

    glGenVertexArrays(1, &triangleVao_);
    describeVertex(triangleVao_, vertices_);
    triangles_ = indexBuffer(mesh.indices);
    triangleIndexCount_ = GLsizei(mesh.indices.size());
    bytes_ += mesh.indices.size() * sizeof(std::uint32_t);

    if (adjacency && !adjacency->indices.empty()) {
        glGenVertexArrays(1, &edgeVao_);
        describeVertex(edgeVao_, vertices_);
        edges_ = indexBuffer(adjacency->indices);
        edgeIndexCount_ = GLsizei(adjacency->indices.size());
        bytes_ += adjacency->indices.size() * sizeof(std::uint32_t);
    }
    glBindVertexArray(0);
}

MeshBuffers::~MeshBuffers() {
    glDeleteVertexArrays(1, &triangleVao_);
    if (edgeVao_) glDeleteVertexArrays(1, &edgeVao_);
    GLuint buffers[] = {vertices_, triangles_, edges_};
    glDeleteBuffers(3, buffers);
}

void MeshBuffers::drawTriangles() const {
    glBindVertexArray(triangleVao_);
    glDrawElements(GL_TRIANGLES, triangleIndexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

void MeshBuffers::drawEdgesWithAdjacency() const {
    if (!edgeVao_) return;
    glBindVertexArray(edgeVao_);
    glDrawElements(GL_LINES_ADJACENCY, edgeIndexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

}  // namespace raylab
