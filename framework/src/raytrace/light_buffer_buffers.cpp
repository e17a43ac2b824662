#include "light_buffer_buffers.h"

#include <vector>

namespace raylab {

LightBufferBuffers::LightBufferBuffers(const LightBuffer& buffer)
    : resolution_(buffer.resolution), everyObjectCell_(buffer.everyObjectCell()),
      reach_(buffer.reach) {
    const std::vector<int> texels = lightCellTexels(buffer);
    const std::vector<GLint> cells(texels.begin(), texels.end());
    std::vector<GLint> items(buffer.items.begin(), buffer.items.end());
    if (items.empty()) items.push_back(-1);  // an empty buffer texture is not allowed everywhere
    textures_.fill(0, GL_RGBA32I, cells.data(), cells.size() * sizeof(GLint));
    textures_.fill(1, GL_R32I, items.data(), items.size() * sizeof(GLint));
}

void LightBufferBuffers::setUniforms(GLuint program) const {
    glUniform1i(glGetUniformLocation(program, "uLightBufferSize"), resolution_);
    glUniform1i(glGetUniformLocation(program, "uLightBufferEveryCell"), everyObjectCell_);
    glUniform1f(glGetUniformLocation(program, "uLightBufferReach"), reach_);
}

}  // namespace raylab
