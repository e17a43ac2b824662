#include "stage_renderer.h"

#include "error.h"
#include "gpu_values.h"
#include "paths.h"
#include "triangle_groups.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace raylab {

namespace {

// Texture units: the scene's pictures, then the sky box.
constexpr int kTextureUnit = 0;
constexpr int kSkyUnit = 1;
constexpr int kBvhNodeUnit = 2;
constexpr int kBvhItemUnit = 3;
constexpr int kMeshCornerUnit = 4;
constexpr int kMeshMaterialUnit = 5;
constexpr int kLightCellUnit = 6;
constexpr int kLightItemUnit = 7;
constexpr int kEyeCellUnit = 8;

void setIntArray(const ShaderProgram& p, const char* name, const std::vector<GLint>& values) {
    if (!values.empty())
        glUniform1iv(p.uniform(std::string(name) + "[0]"), GLsizei(values.size()), values.data());
}

void setFloatArray(const ShaderProgram& p, const char* name, const std::vector<GLfloat>& values) {
    if (!values.empty())
        glUniform1fv(p.uniform(std::string(name) + "[0]"), GLsizei(values.size()), values.data());
}

void setVec4Array(const ShaderProgram& p, const char* name, const std::vector<glm::vec4>& values) {
    if (!values.empty())
        glUniform4fv(p.uniform(std::string(name) + "[0]"), GLsizei(values.size()),
                     glm::value_ptr(values[0]));
}

// Uploads an array uniform NAME[0..] of vec3s when the program has it.
void setVec3Array(const ShaderProgram& p, const char* name, const std::vector<glm::vec3>& values) {
    if (!values.empty())
        glUniform3fv(p.uniform(std::string(name) + "[0]"), GLsizei(values.size()),
                     glm::value_ptr(values[0]));
}

}  // namespace

StageRenderer::StageRenderer(const StageInfo& stage, StageSources sources, Scene scene, int width,
                             int height, PixelFormat format, std::string fragmentEntry,
                             ShaderVariant variant)
    : TargetRenderer(width, height, format), stage_(stage), sources_(std::move(sources)),
      frame_(sceneFrame(scene)), scene_(transformScene(scene, frame_)),
      variant_(std::move(variant)),
      fragmentEntry_(fragmentEntry.empty() ? stage.program.fragment : std::move(fragmentEntry)) {
    // The tracer draws one full-screen canvas: a geometry stage has no place in it.
    if (!stage_.program.geometry.empty())
        throw Error(displayPath(stage_.folder() / "stage.json") +
                    ": program.geometry: the ray tracer's renderer takes no geometry shader");
    checkSceneFits(stage_, scene_);
    variant_.todoMarks = target_->hasTodoMarks();  // a check target counts them
    const SphereArrayLimits sphereLimits = sphereArrayLimits();
    variant_.maxBlockBytes = sphereLimits.uniformBlockBytes;
    if (variant_.sphereStorage && sphereLimits.storageBlockBytes == 0)
        throw Error("storage blocks asked for, but this context has none (OpenGL 4.3)");
    variant_.sphereStorage = variant_.sphereStorage || spheresNeedStorage(scene_, sphereLimits);
    spheres_ = std::make_unique<SphereBlocks>(scene_, sphereSlots(stage_, scene_, variant_),
                                              variant_.sphereStorage);
    if (!scene_.textures.empty()) textures_ = std::make_unique<TextureArray>(scene_.textures);
    if (scene_.skyBox) sky_ = std::make_unique<CubeMap>(*scene_.skyBox);
    rebuild();
}

void StageRenderer::rebuild() {
    StagePrograms programs =
        assembleStagePrograms(stage_, sources_, scene_, variant_, fragmentEntry_);
    const ShaderSource& vertex = programs.vertex;
    if (fragmentRewrite_) programs.fragment = fragmentRewrite_(programs.fragment);
    const ShaderSource& fragment = programs.fragment;
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

    // Spheres: their arrays live in uniform buffers (sphere_blocks.h),
    // uploaded once; the program only learns where to find them.
    glUniform1i(p.uniform("uSphereCount"), GLint(scene_.spheres.size()));
    SphereBlocks::attach(p.id());
    uploadStaticShapes();

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
    std::vector<GLint> texture, normalMap;
    for (const Material& m : scene_.materials) {
        texture.push_back(m.texture);
        normalMap.push_back(m.normalMap);
    }
    setFloatArray(p, "uMatShininess", shininess);
    setFloatArray(p, "uMatIor", ior);
    setIntArray(p, "uMatType", type);
    setIntArray(p, "uMatTexture", texture);
    setIntArray(p, "uMatNormalMap", normalMap);

    // Pictures, sky box and the glowing sphere.
    glUniform1i(p.uniform("uTextures"), kTextureUnit);
    glUniform1i(p.uniform("uSky"), kSkyUnit);
    // The tree is built only for a program that walks it (stage 08 with
    // RAYLAB_BVH), once, on the first such build.
    if (variant_.bvh && !bvh_ && p.uniform("uBvhNodes") >= 0)
        bvh_ = std::make_unique<BvhBuffers>(buildBvh(
            scene_, 2, variant_.treeAll ? BvhObjects::AllBounded : BvhObjects::SpheresAndMeshes));
    glUniform1i(p.uniform("uBvhNodes"), kBvhNodeUnit);
    glUniform1i(p.uniform("uBvhItems"), kBvhItemUnit);
    // The light buffer: built once, for the first program whose shadow rays use it.
    if (!lightBuffer_ && p.uniform("uLightCells") >= 0)
        lightBuffer_ = std::make_unique<LightBufferBuffers>(buildLightBuffer(scene_));
    if (lightBuffer_) lightBuffer_->setUniforms(p.id());
    glUniform1i(p.uniform("uLightCells"), kLightCellUnit);
    glUniform1i(p.uniform("uLightItems"), kLightItemUnit);
    // The eye's cells: built in render(), for the eye of the frame.
    programUsesEyeCells_ = bvh_ && p.uniform("uEyeCells") >= 0;
    // Mesh triangles: uploaded once, for every program of a scene with meshes.
    if (!scene_.meshes.empty() && !meshes_) meshes_ = std::make_unique<SceneMeshBuffers>(scene_);
    glUniform1i(p.uniform("uMeshCorners"), kMeshCornerUnit);
    glUniform1i(p.uniform("uMeshMaterials"), kMeshMaterialUnit);
    glUniform1i(p.uniform("uMeshTriangleCount"), GLint(meshTriangleCount(scene_)));
    glUniform1i(p.uniform("uHasSky"), sky_ ? 1 : 0);
    glUniform1i(p.uniform("uGlowSphere"), scene_.glow.sphere);
    glUniform3fv(p.uniform("uGlowColor"), 1, glm::value_ptr(scene_.glow.color));
    glUniform1f(p.uniform("uGlowSize"), scene_.glow.size);

    // Point lights.
    std::vector<glm::vec3> lightPositions, lightColors;
    for (const PointLight& l : scene_.lights) {
        lightPositions.push_back(gpuPoint(l.position));
        lightColors.push_back(l.color);
    }
    glUniform1i(p.uniform("uLightCount"), GLint(lightPositions.size()));
    setVec3Array(p, "uLightPositions", lightPositions);
    setVec3Array(p, "uLightColors", lightColors);
}

// Planes, discs and triangles never move: uploaded with the constants.
void StageRenderer::uploadStaticShapes() {
    const ShaderProgram& p = *program_;
    std::vector<glm::vec4> planes;
    std::vector<GLfloat> tiles;
    std::vector<GLint> planeMaterial;
    for (const Plane& pl : scene_.planes) {
        planes.push_back(gpuPlane(pl));
        tiles.push_back(float(pl.tileSize));
        planeMaterial.push_back(pl.material);
    }
    glUniform1i(p.uniform("uPlaneCount"), GLint(planes.size()));
    setVec4Array(p, "uPlanes", planes);
    setFloatArray(p, "uPlaneTileSize", tiles);
    setIntArray(p, "uPlaneMaterial", planeMaterial);

    std::vector<glm::vec4> discs;
    std::vector<glm::vec3> discNormals;
    std::vector<GLint> discMaterial;
    for (const Disc& d : scene_.discs) {
        discs.push_back(gpuDisc(d));
        discNormals.push_back(d.normal);
        discMaterial.push_back(d.material);
    }
    glUniform1i(p.uniform("uDiscCount"), GLint(discs.size()));
    setVec4Array(p, "uDiscs", discs);
    setVec3Array(p, "uDiscNormals", discNormals);
    setIntArray(p, "uDiscMaterial", discMaterial);

    std::vector<glm::vec3> vertices;
    std::vector<GLint> triangleMaterial;
    for (const Triangle& t : scene_.triangles) {
        for (const glm::dvec3& v : t.vertices) vertices.push_back(gpuPoint(v));
        triangleMaterial.push_back(t.material);
    }
    glUniform1i(p.uniform("uTriangleCount"), GLint(triangleMaterial.size()));
    setVec3Array(p, "uTriangleVertices", vertices);
    setIntArray(p, "uTriangleMaterial", triangleMaterial);
    std::vector<glm::vec4> groupLow, groupHigh;
    for (const TriangleGroup& g : triangleGroups(scene_)) {
        groupLow.emplace_back(gpuPoint(g.lo), float(g.first));
        groupHigh.emplace_back(gpuPoint(g.hi), float(g.count));
    }
    glUniform1i(p.uniform("uTriangleGroupCount"), GLint(groupLow.size()));
    setVec4Array(p, "uTriangleGroupLow", groupLow);
    setVec4Array(p, "uTriangleGroupHigh", groupHigh);

    std::vector<glm::vec4> tori;
    std::vector<GLfloat> minor;
    std::vector<GLint> torusMaterial;
    for (const Torus& t : scene_.tori) {
        tori.push_back(gpuTorus(t));
        minor.push_back(float(t.minorRadius));
        torusMaterial.push_back(t.material);
    }
    glUniform1i(p.uniform("uTorusCount"), GLint(tori.size()));
    setVec4Array(p, "uTori", tori);
    setFloatArray(p, "uTorusMinor", minor);
    setIntArray(p, "uTorusMaterial", torusMaterial);
}

void StageRenderer::setFragmentRewrite(std::function<ShaderSource(const ShaderSource&)> rewrite) {
    fragmentRewrite_ = std::move(rewrite);
    rebuild();
}

void StageRenderer::render(const Camera& camera, float timeSeconds,
                           const RenderSettings& settings) {
    target_->bind();
    target_->clear(0, 0, 0);
    drawFrame(camera, timeSeconds, settings);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void StageRenderer::renderAt(GLuint framebuffer, int x, int y, int record, const Camera& camera,
                             float timeSeconds, const RenderSettings& settings) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(x, y, target_->width(), target_->height());
    program_->use();
    glUniform1i(program_->uniform("uTraceRecord"), record);
    drawFrame(camera, timeSeconds, settings);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void StageRenderer::drawFrame(const Camera& camera, float timeSeconds,
                              const RenderSettings& settings) {
    const ShaderProgram& p = *program_;
    p.use();
    // The eye moves with the scene into the shaders' frame (in double, then
    // rounded once); directions stay.
    const glm::vec3 eye = gpuPoint(frame_.point(camera.pose().position));
    glUniform3fv(p.uniform("uEye"), 1, glm::value_ptr(eye));
    glUniform3fv(p.uniform("uForward"), 1, glm::value_ptr(camera.forward()));
    glUniform3fv(p.uniform("uRight"), 1, glm::value_ptr(camera.right()));
    glUniform3fv(p.uniform("uUp"), 1, glm::value_ptr(camera.up()));
    glUniform1f(p.uniform("uFocal"), camera.focalLength());
    glUniform1f(p.uniform("uAspect"), float(target_->width()) / float(target_->height()));
    glUniform1f(p.uniform("uTime"), timeSeconds);
    glUniform1i(p.uniform("uShadows"), settings.shadows ? 1 : 0);
    glUniform1i(p.uniform("uMaxDepth"), settings.maxDepth);
    glUniform1i(p.uniform("uGlow"), settings.glow ? 1 : 0);
    glUniform1i(p.uniform("uNormalMaps"), settings.normalMaps ? 1 : 0);
    glUniform1i(p.uniform("uColorMode"), settings.colorMode);
    if (textures_) textures_->bind(kTextureUnit);
    if (sky_) sky_->bind(kSkyUnit);
    if (programUsesEyeCells_) {
        if (!eyeCells_) eyeCells_ = std::make_unique<EyeCellBuffers>();
        eyeCells_->update(scene_, eye, *bvh_);  // when the eye has moved: its lists go into bvh_
        eyeCells_->bind(p.id(), kEyeCellUnit);
    }
    if (bvh_) bvh_->bind(kBvhNodeUnit, kBvhItemUnit);
    if (meshes_) meshes_->bind(kMeshCornerUnit, kMeshMaterialUnit);
    if (lightBuffer_) lightBuffer_->bind(kLightCellUnit, kLightItemUnit);
    // Only sphere positions and torus axes change from frame to frame;
    // the rest of the scene is uploaded once per program, in uploadSceneConstants().
    spheres_->moveTo(timeSeconds);
    spheres_->bind();
    // Spinning tori turn their axis.
    std::vector<glm::mat3> toLocal;
    for (const Torus& t : scene_.tori) toLocal.push_back(torusToLocal(t.axisAt(timeSeconds)));
    if (!toLocal.empty())
        glUniformMatrix3fv(p.uniform("uTorusToLocal[0]"), GLsizei(toLocal.size()), GL_FALSE,
                           glm::value_ptr(toLocal[0]));
    canvas_.draw();
}

}  // namespace raylab
