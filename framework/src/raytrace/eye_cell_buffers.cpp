#include "eye_cell_buffers.h"

#include <glm/gtc/type_ptr.hpp>

#include <vector>

namespace raylab {

void EyeCellBuffers::update(const Scene& scene, glm::vec3 eye, BvhBuffers& bvh) {
    if (built_ && eye == eye_) return;
    const EyeCells built = buildEyeCells(scene, eye, cube_);
    const int base = bvh.setItemTail(built.items);
    const std::vector<int> texels = eyeCellTexels(built, base);
    const std::vector<GLint> cells(texels.begin(), texels.end());
    cells_.fill(GL_RG32I, cells.data(), cells.size() * sizeof(GLint));
    built_ = true;
    eye_ = eye;
}

void EyeCellBuffers::bind(GLuint program, int unit) const {
    cells_.bind(unit);
    glUniform1i(glGetUniformLocation(program, "uEyeCells"), unit);
    glUniform1i(glGetUniformLocation(program, "uEyeCellsSize"), cube_.resolution());
    glUniform3fv(glGetUniformLocation(program, "uEyeCellsCentre"), 1, glm::value_ptr(eye_));
}

}  // namespace raylab
