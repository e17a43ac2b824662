#include "stage_renderer.h"

#include "error.h"

#include <glm/gtc/type_ptr.hpp>

namespace raylab {

namespace {

void checkFits(const Scene& scene, const StageInfo& stage, const char* what, std::size_t count, int limit) {
    if (int(count) > limit)
        throw Error(scene.file + ": " + what + ": " + std::to_string(count) + " " + what + ", but stage " + stage.id +
                    " supports at most " + std::to_string(limit));
}

void checkSceneFits(const StageInfo& stage, const Scene& scene) {
    checkFits(scene, stage, "spheres", scene.spheres.size(), stage.maxSpheres);
    checkFits(scene, stage, "materials", scene.materials.size(), stage.maxMaterials);
    checkFits(scene, stage, "lights", scene.lights.size(), stage.maxLights);
}

// Uploads an array uniform NAME[0..] of vec3s when the program has it.
void setVec3Array(const ShaderProgram& p, const char* name, const std::vector<glm::vec3>& values) {
    if (!values.empty()) glUniform3fv(p.uniform(std::string(name) + "[0]"), GLsizei(values.size()), glm::value_ptr(values[0]));
}

} // namespace

StageRenderer::StageRenderer(const StageInfo& stage, StageSources sources, Scene scene, int width, int height)
    : stage_(stage), sources_(std::move(sources)), scene_(std::move(scene)), target_(std::make_unique<Framebuffer>(width, height)) {
    checkSceneFits(stage_, scene_);
    rebuild();
}

void StageRenderer::rebuild() {
    ShaderSource vertex = assembleShader(kVertexEntry, sources_.search, stage_.defines());
    ShaderSource fragment = assembleShader(kFragmentEntry, sources_.search, stage_.defines());
    auto program = std::make_unique<ShaderProgram>(vertex, fragment);
    program_ = std::move(program);
    files_ = fragment.files;
    files_.insert(files_.end(), vertex.files.begin(), vertex.files.end());
    todos_ = findOpenTodos(fragment);
    uploadSceneConstants();
}

void StageRenderer::uploadSceneConstants() {
    const ShaderProgram& p = *program_;
    p.use();
    glUniform3fv(p.uniform("uBackground"), 1, glm::value_ptr(scene_.background));

    // Spheres: flat colour and material index (positions are set per frame).
    std::vector<glm::vec3> colors;
    std::vector<GLint> materialOf;
    for (const Sphere& s : scene_.spheres) {
        colors.push_back(scene_.materials[std::size_t(s.material)].diffuse);
        materialOf.push_back(s.material);
    }
    glUniform1i(p.uniform("uSphereCount"), GLint(scene_.spheres.size()));
    if (!materialOf.empty()) glUniform1iv(p.uniform("uSphereMaterial[0]"), GLsizei(materialOf.size()), materialOf.data());
    setVec3Array(p, "uSphereColors", colors);

    // The material table.
    std::vector<glm::vec3> ambient, diffuse, specular, metalN, metalK;
    std::vector<GLfloat> shininess, ior;
    std::vector<GLint> type;
    for (const Material& m : scene_.materials) {
        ambient.push_back(m.ambient);
        diffuse.push_back(m.diffuse);
        specular.push_back(m.specular);
        shininess.push_back(m.shininess);
        type.push_back(GLint(m.type));
        ior.push_back(m.ior);
        metalN.push_back(m.n);
        metalK.push_back(m.k);
    }
    setVec3Array(p, "uMatAmbient", ambient);
    setVec3Array(p, "uMatDiffuse", diffuse);
    setVec3Array(p, "uMatSpecular", specular);
    setVec3Array(p, "uMatN", metalN);
    setVec3Array(p, "uMatK", metalK);
    if (!type.empty()) {
        glUniform1fv(p.uniform("uMatShininess[0]"), GLsizei(shininess.size()), shininess.data());
        glUniform1fv(p.uniform("uMatIor[0]"), GLsizei(ior.size()), ior.data());
        glUniform1iv(p.uniform("uMatType[0]"), GLsizei(type.size()), type.data());
    }

    // Point lights.
    std::vector<glm::vec3> lightPositions, lightColors;
    for (const PointLight& l : scene_.lights) {
        lightPositions.push_back(l.position);
        lightColors.push_back(l.color);
    }
    glUniform1i(p.uniform("uLightCount"), GLint(lightPositions.size()));
    setVec3Array(p, "uLightPositions", lightPositions);
    setVec3Array(p, "uLightColors", lightColors);
}

void StageRenderer::render(const Camera& camera, float timeSeconds, const RenderSettings& settings) {
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
    glUniform1i(p.uniform("uShadows"), settings.shadows ? 1 : 0);
    glUniform1i(p.uniform("uMaxDepth"), settings.maxDepth);
    // Only sphere positions change from frame to frame (moving spheres);
    // the rest of the scene is uploaded once per program, in uploadSceneConstants().
    std::vector<glm::vec4> spheres;
    for (const Sphere& s : scene_.spheres) spheres.emplace_back(s.center + s.motion.offsetAt(timeSeconds), s.radius);
    if (!spheres.empty()) glUniform4fv(p.uniform("uSpheres[0]"), GLsizei(spheres.size()), glm::value_ptr(spheres[0]));
    canvas_.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace raylab
