#include "fur_renderer.h"

#include "error.h"
#include "fin_count.h"
#include "mesh_shapes.h"
#include "obj_mesh.h"
#include "paths.h"

#ifndef RAYLAB_REFERENCES_AS_DATA
#include "silhouette.h"
#endif

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace raylab {

namespace {

// Texture units, as fur_uniforms.glsl binds its samplers.
constexpr int kColorUnit = 0, kPatternUnit = 1, kFinUnit = 2;

// The near and far planes hug the mesh's bounding sphere (with room for the
// fur), so the mesh is drawn at any size and distance and the depth buffer
// keeps its precision; from inside the sphere the near plane is a small
// share of the far one.
constexpr float kNearShareOfFar = 1e-4f;

// "Over" blending for the see-through layers (the frame's own alpha is
// masked off in render()).
void blendOver() {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}

}  // namespace

StrandBudget driverStrandBudget(int segments) {
    GLint maxVertices = 0, maxComponents = 0;
    glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &maxVertices);
    glGetIntegerv(GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, &maxComponents);
    return strandBudget(maxVertices, maxComponents, segments);
}

struct FurRenderer::Frame {
    glm::mat4 model, view, projection;
    glm::vec3 eye;
    float time;
    float furLength;
    RenderSettings settings;
};

FurRenderer::FurRenderer(const StageInfo& stage, StageSources sources, FurScene scene, int width,
                         int height, PixelFormat format)
    : TargetRenderer(width, height, format), stage_(stage), sources_(std::move(sources)),
      scene_(std::move(scene)) {
    if (!stage_.has("mesh"))
        throw Error(displayPath(stage_.folder() / "stage.json") +
                    ": features: a fur stage needs the \"mesh\" feature");
    colorMap_ = std::make_unique<Texture2D>(scene_.fur.colorMap);
    pattern_ = std::make_unique<Texture2D>(scene_.fur.pattern);
    finMap_ = std::make_unique<Texture2D>(scene_.fur.finMap);
    if (stage_.has("fur_shader")) budget_ = driverStrandBudget(scene_.fur.strandSegments);
    setMesh(loadFurMesh(scene_, &placement_));
    rebuild();
}

std::string FurRenderer::sceneNote() const {
    return describePlacement(placement_, displayPath(scene_.mesh.obj));
}

void FurRenderer::setMesh(Mesh mesh) {
    validateMesh(mesh);
    mesh_ = std::move(mesh);
    const BoundingSphere bounds = boundingSphere(mesh_);
    boundsCentre_ = bounds.centre;
    boundsRadius_ = bounds.radius;
    adjacency_ = stage_.has("fins") ? buildEdgeAdjacency(mesh_) : EdgeAdjacency{};
    buffers_ = std::make_unique<MeshBuffers>(mesh_, stage_.has("fins") ? &adjacency_ : nullptr);
    feedCorners();
}

void FurRenderer::feedCorners() {
    // Each input primitive's corners one after the other (position, normal,
    // uv at locations 0, 1, 2, as the mesh's vertex buffer has them).
    auto corners = [&](const std::vector<std::uint32_t>& indices) {
        std::vector<float> out;
        out.reserve(indices.size() * 8);
        for (std::uint32_t i : indices) {
            const glm::vec3 &p = mesh_.positions[i], &n = mesh_.normals[i];
            const glm::vec2& uv = mesh_.uvs[i];
            out.insert(out.end(), {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
        }
        return out;
    };
    const std::vector<std::pair<int, int>> attributes = {{0, 3}, {1, 3}, {2, 2}};
    if (finsEmulated_) finsEmulated_->setCorners(corners(adjacency_.indices), attributes);
    if (strandsEmulated_) strandsEmulated_->setCorners(corners(mesh_.indices), attributes);
}

void FurRenderer::setGeometryEmulation(bool on) {
    emulate_ = on;
    rebuild();
}

void FurRenderer::rebuild() {
    std::vector<std::string> defines = stage_.defines();
    if (target_->hasTodoMarks()) defines.push_back("RAYLAB_TODO_MARK");  // a check target
    if (stage_.has("fur_shader"))
        for (const std::string& d : budget_.defines()) defines.push_back(d);
    const std::vector<std::filesystem::path> search = searchWithVariants(sources_, defines);
    std::vector<std::filesystem::path> files;
    std::vector<OpenTodo> todos;
    std::set<std::pair<std::string, int>> seen;
    auto assemble = [&](const std::string& entry) {
        ShaderSource s = assembleShader(entry, search, defines);
        files.insert(files.end(), s.files.begin(), s.files.end());
        for (const OpenTodo& t : findOpenTodos(s))
            if (seen.insert({t.file, t.line}).second) todos.push_back(t);
        return s;
    };
    auto build = [&](const StageProgram& p) {
        ShaderSource vertex = assemble(p.vertex);
        ShaderSource fragment = assemble(p.fragment);
        if (p.geometry.empty()) return std::make_unique<ShaderProgram>(vertex, fragment);
        ShaderSource geometry = assemble(p.geometry);
        return std::make_unique<ShaderProgram>(vertex, geometry, fragment);
    };
    auto emulated = [&](const StageProgram& p) -> std::unique_ptr<EmulatedGeometryPass> {
        if (!emulate_ || p.geometry.empty()) return nullptr;
        ShaderSource vertex = assemble(p.vertex);
        ShaderSource geometry = assemble(p.geometry);
        return std::make_unique<EmulatedGeometryPass>(vertex, geometry, assemble(p.fragment));
    };
    // Built into locals first: a failure leaves the previous programs in use.
    auto shells = build(stage_.program);
    auto fins = stage_.has("fins") ? build(namedProgram(stage_, "fins", "fins")) : nullptr;
    auto strands =
        stage_.has("fur_shader") ? build(namedProgram(stage_, "strands", "fur_shader")) : nullptr;
    auto finsEmulated =
        stage_.has("fins") ? emulated(namedProgram(stage_, "fins", "fins")) : nullptr;
    auto strandsEmulated = stage_.has("fur_shader")
                               ? emulated(namedProgram(stage_, "strands", "fur_shader"))
                               : nullptr;
    shells_ = std::move(shells);
    fins_ = std::move(fins);
    strands_ = std::move(strands);
    finsEmulated_ = std::move(finsEmulated);
    strandsEmulated_ = std::move(strandsEmulated);
    if (buffers_) feedCorners();
    files_ = std::move(files);
    todos_ = std::move(todos);
}

void FurRenderer::setUniforms(const ShaderProgram& p, const Frame& f) const {
    p.use();
    glUniformMatrix4fv(p.uniform("uModel"), 1, GL_FALSE, glm::value_ptr(f.model));
    glUniformMatrix4fv(p.uniform("uView"), 1, GL_FALSE, glm::value_ptr(f.view));
    glUniformMatrix4fv(p.uniform("uProjection"), 1, GL_FALSE, glm::value_ptr(f.projection));
    glUniform3fv(p.uniform("uEye"), 1, glm::value_ptr(f.eye));
    glUniform3fv(p.uniform("uLightDir"), 1, glm::value_ptr(scene_.lightDirection));
    glUniform3fv(p.uniform("uLightColor"), 1, glm::value_ptr(scene_.lightColor));
    glUniform3fv(p.uniform("uAmbient"), 1, glm::value_ptr(scene_.ambient));
    glUniform1f(p.uniform("uFurLength"), f.furLength);
    glUniform1f(p.uniform("uPatternScale"), scene_.fur.patternScale);
    glUniform1f(p.uniform("uShadowIntensity"), scene_.fur.shadowIntensity);
    const glm::vec3 gravity(0.0f, -scene_.fur.gravity, 0.0f);
    glUniform3fv(p.uniform("uGravity"), 1, glm::value_ptr(gravity));
    glUniform1f(p.uniform("uStrandDensity"), scene_.fur.strandDensity);
    glUniform1f(p.uniform("uTime"), f.time);
    glUniform1i(p.uniform("uColorMap"), kColorUnit);
    glUniform1i(p.uniform("uPattern"), kPatternUnit);
    glUniform1i(p.uniform("uFinMap"), kFinUnit);
}

void FurRenderer::setUniforms(const EmulatedGeometryPass& pass, const Frame& f) const {
    setUniforms(pass.capture(), f);
    setUniforms(pass.expand(), f);
    setUniforms(pass.draw(), f);
}

void FurRenderer::drawSkinAndShells(const Frame& f, int shells) {
    const ShaderProgram& p = *shells_;
    setUniforms(p, f);
    glUniform1i(p.uniform("uShellCount"), shells);
    // Draw 0 is the skin: opaque, it writes depth so that what it hides
    // stays hidden. The shells after it are see-through: blended in the
    // order they are drawn, which must be from the skin outwards (the
    // shell program's shellLayer() decides which layer draw i is). They
    // test depth but do not write it, so a shell never hides the shells
    // drawn after it (lab guide f2, "Why the order matters").
    for (int i = 0; i < shells; ++i) {
        if (i == 1) {
            glDepthMask(GL_FALSE);
            blendOver();
        }
        glUniform1i(p.uniform("uShellIndex"), i);
        buffers_->drawTriangles();
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

void FurRenderer::drawFins(const Frame& f) {
    if (finsEmulated_) {
        setUniforms(*finsEmulated_, f);
    } else {
        setUniforms(*fins_, f);
    }
    // Fins are thin quads seen from either side; blended like the shells.
    const GLboolean culling = glIsEnabled(GL_CULL_FACE);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_FALSE);
    blendOver();
    if (finsEmulated_) finsEmulated_->run();
    else buffers_->drawEdgesWithAdjacency();
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    if (culling) glEnable(GL_CULL_FACE);
}

void FurRenderer::drawStrands(const Frame& f) {
    if (strandsEmulated_) {
        setUniforms(*strandsEmulated_, f);
        strandsEmulated_->run();
        return;
    }
    setUniforms(*strands_, f);
    buffers_->drawTriangles();
}

FurRenderer::Frame FurRenderer::frameFor(const Camera& camera, float timeSeconds,
                                         const RenderSettings& settings) const {
    // Fur draws in float: a fur scene's model sits at the origin.
    const glm::vec3 eye(camera.pose().position);
    Frame f;
    f.model = scene_.modelMatrix(timeSeconds);
    f.view = glm::lookAt(eye, eye + camera.forward(), camera.up());
    const float furLength = scene_.fur.length * settings.furLength;
    // The bounding sphere in world space: the model's largest scale, and the
    // fur (bent strands reach at most (1 + gravity) of its length out).
    const glm::vec3 centre = glm::vec3(f.model * glm::vec4(boundsCentre_, 1.0f));
    const float scale =
        std::max({glm::length(glm::vec3(f.model[0])), glm::length(glm::vec3(f.model[1])),
                  glm::length(glm::vec3(f.model[2]))});
    const float radius = boundsRadius_ * scale + furLength * (1.0f + scene_.fur.gravity) * 1.05f;
    const float distance = glm::length(eye - centre);
    const float far = distance + radius;
    const float near = std::max(far * kNearShareOfFar, distance - radius);
    f.projection = glm::perspective(glm::radians(camera.fovYDeg()),
                                    float(target_->width()) / float(target_->height()), near, far);
    f.eye = eye;
    f.time = timeSeconds;
    f.furLength = furLength;
    f.settings = settings;
    return f;
}

void FurRenderer::render(const Camera& camera, float timeSeconds, const RenderSettings& settings) {
    if (settings.furMesh != meshShown_) {  // the window's mesh key
        const std::vector<std::string>& shapes = shapeNames();
        const int i = settings.furMesh;
        setMesh(
            i > 0 && i <= int(shapes.size())
                ? makeShape(shapes[std::size_t(i - 1)], defaultDetail(shapes[std::size_t(i - 1)]))
                : loadFurMesh(scene_));
        meshShown_ = settings.furMesh;
    }
    const Frame f = frameFor(camera, timeSeconds, settings);

    target_->bind();
    target_->clear(scene_.background.r, scene_.background.g, scene_.background.b);
    // The frame is a picture: its alpha stays the clear's 1. The shaders'
    // alpha drives blending and discard only (a skin drawn with alpha 0.3
    // must not make a see-through PNG).
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // a shell at the skin (layer 0 again) still draws
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    colorMap_->bind(kColorUnit);
    pattern_->bind(kPatternUnit);
    finMap_->bind(kFinUnit);

    const bool furShader = stage_.has("fur_shader") && settings.furTechnique == 1;
    const int shells = !stage_.has("shells") || furShader
                           ? 1
                           : (settings.shells > 0 ? settings.shells : scene_.fur.shells);
    drawSkinAndShells(f, shells);
    if (furShader) drawStrands(f);
    else if (stage_.has("fins") && settings.fins) drawFins(f);

    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

long FurRenderer::countFins(const Camera& camera, float timeSeconds,
                            const RenderSettings& settings) {
    if (!fins_) throw Error("stage " + stage_.id + " draws no fins");
    return countPrimitives(false, frameFor(camera, timeSeconds, settings)) / 2;
}

long FurRenderer::countStrandSegments(const Camera& camera, float timeSeconds,
                                      const RenderSettings& settings) {
    if (!strands_) throw Error("stage " + stage_.id + " draws no strands");
    return countPrimitives(true, frameFor(camera, timeSeconds, settings));
}

long FurRenderer::countPrimitives(bool strands, const Frame& f) {
    target_->bind();
    EmulatedGeometryPass* emulated = strands ? strandsEmulated_.get() : finsEmulated_.get();
    long primitives = 0;
    if (emulated) {
        setUniforms(*emulated, f);
        primitives = emulated->run(true);
    } else {
        GLuint query = 0;
        glGenQueries(1, &query);
        // Counted, not drawn: the frame in the target stays as it was.
        glEnable(GL_RASTERIZER_DISCARD);
        glBeginQuery(GL_PRIMITIVES_GENERATED, query);
        if (strands) drawStrands(f);
        else drawFins(f);
        glEndQuery(GL_PRIMITIVES_GENERATED);
        glDisable(GL_RASTERIZER_DISCARD);
        GLuint64 generated = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &generated);
        glDeleteQueries(1, &query);
        primitives = long(generated);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return primitives;
}

CountResult FurRenderer::countCheck(const std::string& name, const Camera& camera,
                                    float timeSeconds, const RenderSettings& settings) {
    if (name != "fin_count") return TrackRenderer::countCheck(name, camera, timeSeconds, settings);
    CountResult r;
    r.applies = fins_ && settings.fins && settings.furTechnique == 0;
    if (!r.applies) return r;
    r.measured = countFins(camera, timeSeconds, settings);
    r.outOf = long(adjacency_.edgeCount());
#ifndef RAYLAB_REFERENCES_AS_DATA
    const SilhouetteCount cpu =
        countSilhouettes(mesh_, adjacency_, glm::dmat4(scene_.modelMatrix(timeSeconds)),
                         glm::dvec3(camera.pose().position));
    const FinCountVerdict v = judgeFinCount(r.measured, adjacency_.edgeCount(), cpu);
    r.passed = v.passed;
    r.detail = v.detail;
#else
    r.measuredOnly = true;  // the silhouette count is TODO f3.a's answer: count_tables.h
#endif
    return r;
}

std::size_t FurRenderer::gpuBytes(const RenderSettings& settings) const {
    // Mipmapped RGBA8: the levels below the picture add a third.
    auto texels = [](const Texture2D& t) {
        return std::size_t(t.width()) * t.height() * 4 * 4 / 3;
    };
    // Every technique draws the skin with the shell program (colour map and
    // pattern); fins add the adjacency indices and the fin map.
    std::size_t bytes =
        buffers_->bytes() - buffers_->adjacencyBytes() + texels(*colorMap_) + texels(*pattern_);
    if (settings.furTechnique == 0 && settings.fins && fins_)
        bytes += buffers_->adjacencyBytes() + texels(*finMap_);
    return bytes;
}

}  // namespace raylab
