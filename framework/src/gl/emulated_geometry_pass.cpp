#include "emulated_geometry_pass.h"

namespace raylab {

EmulatedGeometryPass::EmulatedGeometryPass(const ShaderSource& vertex, const ShaderSource& geometry,
                                           const ShaderSource& fragment)
    : layout_(emulateGeometryShader(vertex, geometry)) {
    capture_ = std::make_unique<ShaderProgram>(vertex, captureFragmentShader(), layout_.captured);
    draw_ = std::make_unique<ShaderProgram>(layout_.vertex, fragment,
                                            std::vector<std::string>{kEmulationKeptOutput});
    glGenVertexArrays(1, &cornerVao_);
    glGenVertexArrays(1, &recordVao_);
    GLuint buffers[3];
    glGenBuffers(3, buffers);
    corners_ = buffers[0];
    records_ = buffers[1];
    kept_ = buffers[2];
}

EmulatedGeometryPass::~EmulatedGeometryPass() {
    glDeleteVertexArrays(1, &cornerVao_);
    glDeleteVertexArrays(1, &recordVao_);
    GLuint buffers[] = {corners_, records_, kept_};
    glDeleteBuffers(3, buffers);
}

void EmulatedGeometryPass::setCorners(const std::vector<float>& floats,
                                      const std::vector<std::pair<int, int>>& attributes) {
    int perCorner = 0;
    for (const auto& a : attributes) perCorner += a.second;
    cornerCount_ = perCorner ? long(floats.size()) / perCorner : 0;
    glBindVertexArray(cornerVao_);
    glBindBuffer(GL_ARRAY_BUFFER, corners_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(floats.size() * sizeof(float)), floats.data(),
                 GL_STATIC_DRAW);
    std::size_t offset = 0;
    for (const auto& [location, size] : attributes) {
        glEnableVertexAttribArray(GLuint(location));
        glVertexAttribPointer(GLuint(location), size, GL_FLOAT, GL_FALSE,
                              GLsizei(perCorner * sizeof(float)),
                              reinterpret_cast<const void*>(offset));
        offset += std::size_t(size) * sizeof(float);
    }
    // The records: one per corner, read per primitive as uvec4 attributes.
    // (16 bytes more: the last attribute may read past the last record.)
    const std::size_t recordBytes = std::size_t(layout_.recordWords) * 4;
    glBindBuffer(GL_ARRAY_BUFFER, records_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(std::size_t(cornerCount_) * recordBytes + 16), nullptr,
                 GL_DYNAMIC_COPY);
    glBindVertexArray(recordVao_);
    const GLsizei stride = GLsizei(std::size_t(layout_.corners) * recordBytes);
    for (int a = 0; a < layout_.attributes; ++a) {
        const GLint location =
            glGetAttribLocation(draw_->id(), ("raylab_in" + std::to_string(a)).c_str());
        if (location < 0) continue;  // not read
        glEnableVertexAttribArray(GLuint(location));
        glVertexAttribIPointer(GLuint(location), 4, GL_UNSIGNED_INT, stride,
                               reinterpret_cast<const void*>(std::size_t(16 * a)));
        glVertexAttribDivisor(GLuint(location), 1);
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

long EmulatedGeometryPass::run(bool count) {
    const GLsizei primitives = GLsizei(cornerCount_ / layout_.corners);
    if (!primitives) return 0;
    // 1. The vertex shader per corner, its outputs kept.
    capture_->use();
    glEnable(GL_RASTERIZER_DISCARD);
    glBindVertexArray(cornerVao_);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, records_);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, GLsizei(cornerCount_));
    glEndTransformFeedback();
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    if (!count) glDisable(GL_RASTERIZER_DISCARD);

    // 2. The geometry shader per output primitive's corner.
    const GLenum mode = layout_.output == EmulatedOutput::Points  ? GL_POINTS
                        : layout_.output == EmulatedOutput::Lines ? GL_LINES
                                                                  : GL_TRIANGLES;
    const GLsizei vertices = GLsizei(layout_.verticesPerPrimitive());
    draw_->use();
    glBindVertexArray(recordVao_);
    long made = 0;
    if (count) {
        const std::size_t n = std::size_t(vertices) * std::size_t(primitives);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, kept_);
        glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(n * sizeof(GLint)), nullptr,
                     GL_DYNAMIC_READ);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, kept_);
        glBeginTransformFeedback(mode);
        glDrawArraysInstanced(mode, 0, vertices, primitives);
        glEndTransformFeedback();
        std::vector<GLint> kept(n);
        glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(n * sizeof(GLint)),
                           kept.data());
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        glDisable(GL_RASTERIZER_DISCARD);
        for (GLint k : kept) made += k;
        made /= layout_.verticesPerSlot;
    } else {
        glDrawArraysInstanced(mode, 0, vertices, primitives);
    }
    glBindVertexArray(0);
    return made;
}

}  // namespace raylab
