#include "light_buffer_buffers.h"

#include "bvh_buffers.h"

#include <vector>

namespace raylab {

LightBufferBuffers::LightBufferBuffers(const LightBuffer& buffer)
    : resolution_(buffer.resolution), everyObjectCell_(buffer.everyObjectCell()),
      reach_(buffer.reach) {
    std::vector<GLint> cells;
    for (glm::ivec4 c : buffer.cells) cells.insert(cells.end(), {c.x, c.y, c.z, c.w});
    std::vector<GLint> items(buffer.items.begin(), buffer.items.end());
    if (items.empty()) items.push_back(-1);  // an empty buffer texture is not allowed everywhere
    glGenBuffers(2, buffers_);
    glGenTextures(2, textures_);
    fillTextureBuffer(buffers_[0], textures_[0], GL_RGBA32I, cells.data(),
                      cells.size() * sizeof(GLint));
    fillTextureBuffer(buffers_[1], textures_[1], GL_R32I, items.data(),
                      items.size() * sizeof(GLint));
}

LightBufferBuffers::~LightBufferBuffers() {
    glDeleteTextures(2, textures_);
    glDeleteBuffers(2, buffers_);
}

void LightBufferBuffers::bind(int cellUnit, int itemUnit) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + cellUnit));
    glBindTexture(GL_TEXTURE_BUFFER, textures_[0]);
    glActiveTexture(GLenum(GL_TEXTURE0 + itemUnit));
    glBindTexture(GL_TEXTURE_BUFFER, textures_[1]);
    glActiveTexture(GL_TEXTURE0);
}

void LightBufferBuffers::setUniforms(GLuint program) const {
    glUniform1i(glGetUniformLocation(program, "uLightBufferSize"), resolution_);
    glUniform1i(glGetUniformLocation(program, "uLightBufferEveryCell"), everyObjectCell_);
    glUniform1f(glGetUniformLocation(program, "uLightBufferReach"), reach_);
}

}  // namespace raylab
