#include "stage_renderer.h"

#include "error.h"

#include <glm/gtc/type_ptr.hpp>

namespace raylab {

namespace {

void checkSceneFits(const StageInfo& stage, const Scene& scene) {
    if (int(scene.spheres.size()) > stage.maxSpheres)
        throw Error(scene.file + ": spheres: " + std::to_string(scene.spheres.size()) + " spheres, but stage " + stage.id +
                    " supports at most " + std::to_string(stage.maxSpheres));
}

} // namespace

StageRenderer::StageRenderer(const StageInfo& stage, StageSources sources, Scene scene, int width, int height)
    : stage_(stage), sources_(std::move(sources)), scene_(std::move(scene)), target_(std::make_unique<Framebuffer>(width, height)) {
    checkSceneFits(stage_, scene_);
    rebuild();
}

void StageRenderer::rebuild() {
    ShaderSource vertex = assembleShader(kVertexEntry, sources_.search, stage_.defines);
    ShaderSource fragment = assembleShader(kFragmentEntry, sources_.search, stage_.defines);
    auto program = std::make_unique<ShaderProgram>(vertex, fragment);
    program_ = std::move(program);
    files_ = fragment.files;
    files_.insert(files_.end(), vertex.files.begin(), vertex.files.end());
    todos_ = findOpenTodos(fragment);
}

void StageRenderer::render(const Camera& camera, float timeSeconds) {
    target_->bind();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    const ShaderProgram& p = *program_;
    p.use();
    const CameraPose& pose = camera.pose();
    glUniform3fv(p.uniform("uEye"), 1, glm::value_ptr(pose.position));
    glUniform3fv(p.uniform("uForward"), 1, glm::value_ptr(camera.forward()));
    glUniform3fv(p.uniform("uRight"), 1, glm::value_ptr(camera.right()));
    glUniform3fv(p.uniform("uUp"), 1, glm::value_ptr(camera.up()));
    glUniform1f(p.uniform("uFocal"), camera.focalLength());
    glUniform1f(p.uniform("uAspect"), float(target_->width()) / float(target_->height()));
    glUniform1f(p.uniform("uTime"), timeSeconds);
    glUniform3fv(p.uniform("uBackground"), 1, glm::value_ptr(scene_.background));

    std::vector<glm::vec4> spheres;
    std::vector<glm::vec3> colors;
    for (const Sphere& s : scene_.spheres) {
        spheres.emplace_back(s.center + s.motion.offsetAt(timeSeconds), s.radius);
        colors.push_back(s.color);
    }
    glUniform1i(p.uniform("uSphereCount"), GLint(spheres.size()));
    if (!spheres.empty()) {
        glUniform4fv(p.uniform("uSpheres[0]"), GLsizei(spheres.size()), glm::value_ptr(spheres[0]));
        glUniform3fv(p.uniform("uSphereColors[0]"), GLsizei(colors.size()), glm::value_ptr(colors[0]));
    }
    canvas_.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace raylab
