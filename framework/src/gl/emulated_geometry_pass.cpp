#include "emulated_geometry_pass.h"

namespace raylab {

EmulatedGeometryPass::EmulatedGeometryPass(const ShaderSource& vertex, const ShaderSource& geometry,
                                           const ShaderSource& fragment)
    : layout_(emulateGeometryShader(vertex, geometry)) {
    capture_ = std::make_unique<ShaderProgram>(vertex, captureFragmentShader(), layout_.captured);
    expand_ =
        std::make_unique<ShaderProgram>(layout_.expand, captureFragmentShader(), layout_.emitted);
    draw_ = std::make_unique<ShaderProgram>(layout_.draw, fragment,
                                            std::vector<std::string>{kEmulationKeptOutput});
    draw_->use();
    glUniform1i(glGetUniformLocation(draw_->id(), kEmissionSampler), kEmissionTextureUnit);
    glUseProgram(0);
    GLuint vaos[3];
    glGenVertexArrays(3, vaos);
    cornerVao_ = vaos[0];
    recordVao_ = vaos[1];
    emptyVao_ = vaos[2];
    GLuint buffers[4];
    glGenBuffers(4, buffers);
    corners_ = buffers[0];
    records_ = buffers[1];
    emissions_ = buffers[2];
    kept_ = buffers[3];
    glGenTextures(1, &emissionTexture_);
}

EmulatedGeometryPass::~EmulatedGeometryPass() {
    GLuint vaos[] = {cornerVao_, recordVao_, emptyVao_};
    glDeleteVertexArrays(3, vaos);
    GLuint buffers[] = {corners_, records_, emissions_, kept_};
    glDeleteBuffers(4, buffers);
    glDeleteTextures(1, &emissionTexture_);
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
    // The records: one per corner, read per primitive (the expand's vertex)
    // as uvec4 attributes.
    // (16 bytes more: the last attribute may read past the last record.)
    const std::size_t recordBytes = std::size_t(layout_.recordWords) * 4;
    glBindBuffer(GL_ARRAY_BUFFER, records_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(std::size_t(cornerCount_) * recordBytes + 16), nullptr,
                 GL_DYNAMIC_COPY);
    glBindVertexArray(recordVao_);
    const GLsizei stride = GLsizei(std::size_t(layout_.corners) * recordBytes);
    for (int a = 0; a < layout_.attributes; ++a) {
        const GLint location =
            glGetAttribLocation(expand_->id(), ("raylab_in" + std::to_string(a)).c_str());
        if (location < 0) continue;  // not read
        glEnableVertexAttribArray(GLuint(location));
        glVertexAttribIPointer(GLuint(location), 4, GL_UNSIGNED_INT, stride,
                               reinterpret_cast<const void*>(std::size_t(16 * a)));
    }
    glBindVertexArray(0);
    // The emissions: written by transform feedback, copied into the texture.
    const long primitives = cornerCount_ / layout_.corners;
    draw_->use();
    glUniform1i(glGetUniformLocation(draw_->id(), kEmulationPrimitivesUniform), GLint(primitives));
    glUseProgram(0);
    textureSize_ = emissionTextureSize(layout_, primitives);
    glBindBuffer(GL_ARRAY_BUFFER, emissions_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(textureSize_.bytes()), nullptr, GL_DYNAMIC_COPY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glActiveTexture(GL_TEXTURE0 + kEmissionTextureUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, emissionTexture_);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32UI, kEmissionTextureWidth, textureSize_.rows,
                 textureSize_.layers, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, nullptr);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE0);
}

long EmulatedGeometryPass::run(bool count) {
    const GLsizei primitives = GLsizei(cornerCount_ / layout_.corners);
    if (!primitives) return 0;
    glEnable(GL_RASTERIZER_DISCARD);
    // 1. The vertex shader per corner, its outputs kept.
    capture_->use();
    glBindVertexArray(cornerVao_);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, records_);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, GLsizei(cornerCount_));
    glEndTransformFeedback();

    // 2. The geometry shader's body: a vertex per input primitive, an
    // instance per run, its emissions kept.
    expand_->use();
    glBindVertexArray(recordVao_);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, emissions_);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArraysInstanced(GL_POINTS, 0, primitives, layout_.runs);
    glEndTransformFeedback();
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    if (!count) glDisable(GL_RASTERIZER_DISCARD);

    // 3. The emissions into the texture the draw reads.
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, emissions_);
    glActiveTexture(GL_TEXTURE0 + kEmissionTextureUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, emissionTexture_);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, kEmissionTextureWidth, textureSize_.rows,
                    textureSize_.layers, GL_RGBA_INTEGER, GL_UNSIGNED_INT, nullptr);
    glActiveTexture(GL_TEXTURE0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);

    // 4. The primitives, one vertex per (input primitive, slot, corner).
    const GLenum mode = layout_.output == EmulatedOutput::Points  ? GL_POINTS
                        : layout_.output == EmulatedOutput::Lines ? GL_LINES
                                                                  : GL_TRIANGLES;
    const std::size_t n = std::size_t(layout_.verticesPerPrimitive()) * std::size_t(primitives);
    draw_->use();
    glBindVertexArray(emptyVao_);
    long made = 0;
    if (count) {
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, kept_);
        glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(n * sizeof(GLint)), nullptr,
                     GL_DYNAMIC_READ);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, kept_);
        glBeginTransformFeedback(mode);
        glDrawArrays(mode, 0, GLsizei(n));
        glEndTransformFeedback();
        std::vector<GLint> kept(n);
        glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(n * sizeof(GLint)),
                           kept.data());
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        glDisable(GL_RASTERIZER_DISCARD);
        for (GLint k : kept) made += k;
        made /= layout_.verticesPerSlot;
    } else {
        glDrawArrays(mode, 0, GLsizei(n));
    }
    glBindVertexArray(0);
    return made;
}

}  // namespace raylab
