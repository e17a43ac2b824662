#pragma once
// The fur track's renderer. Every frame it rasterises the scene's mesh:
//   1. the skin (draw 0 of the shell program: opaque, writes depth);
//   2. shells+fins: draws 1..N-1 of the shell program, each a layer further
//      out, blended over what is there, depth tested but not written; then
//      the fins, one geometry-shader invocation per edge (GL_LINES_ADJACENCY);
//   2'. fur shader: one geometry-shader invocation per triangle that writes
//      line strips (strands), depth tested and written.
// Which of these a stage draws follows its features (mesh, shells, fins,
// fur_shader); its programs are stage.json's "program" (skin and shells),
// "programs.fins" and "programs.strands".
#include "emulated_geometry_pass.h"
#include "framebuffer.h"
#include "fur_scene.h"
#include "mesh.h"
#include "mesh_buffers.h"
#include "render_settings.h"
#include "shader_program.h"
#include "stage_catalog.h"
#include "stage_sources.h"
#include "strand_budget.h"
#include "target_renderer.h"
#include "texture.h"

#include <memory>
#include <optional>

namespace raylab {

// The strand budget (strand_budget.h) of the current GL context's driver for
// strands of SEGMENTS segments: what the fur shader's program is compiled for.
StrandBudget driverStrandBudget(int segments);

class FurRenderer : public TargetRenderer {
public:
    // Needs a current GL context. Throws Error (bad scene or mesh, missing
    // file) or ShaderError (compile or link error, mapped to file:line).
    FurRenderer(const StageInfo& stage, StageSources sources, FurScene scene, int width, int height,
                PixelFormat format = PixelFormat::Rgba8);

    void render(const Camera& camera, float timeSeconds,
                const RenderSettings& settings = {}) override;
    void rebuild() override;
    const std::vector<std::filesystem::path>& sourceFiles() const override { return files_; }
    const std::vector<OpenTodo>& openTodos() const override { return todos_; }
    std::string sceneNote() const override;

    void completeSettings(RenderSettings& settings) const override {
        if (settings.shells == 0) settings.shells = scene_.fur.shells;
    }

    // "fin_count": the fins the geometry shader emits (countFins) against
    // the silhouette edges counted in double precision (silhouette.h).
    CountResult countCheck(const std::string& name, const Camera& camera, float timeSeconds,
                           const RenderSettings& settings) override;

    // Draws the mesh given instead of the scene's (the window's mesh key, the bench).
    void setMesh(Mesh mesh);
    const Mesh& mesh() const { return mesh_; }
    const EdgeAdjacency& adjacency() const { return adjacency_; }
    const FurScene& scene() const { return scene_; }
    const StrandBudget& strandBudget() const { return budget_; }

    // Runs only the fin pass of a frame and returns how many fins its
    // geometry shader emitted (a GL_PRIMITIVES_GENERATED query: each fin is
    // a strip of two triangles). Needs the "fins" feature.
    long countFins(const Camera& camera, float timeSeconds, const RenderSettings& settings = {});
    // The line segments the fur shader's strands are made of (same query).
    long countStrandSegments(const Camera& camera, float timeSeconds,
                             const RenderSettings& settings = {});

    // Draws fins and strands as the page does, without a geometry shader
    // (emulated_geometry_pass.h): for the tests that compare the two ways.
    // Rebuilds the programs.
    void setGeometryEmulation(bool on);
    bool emulatesGeometry() const { return emulate_; }

    // Bytes of GPU buffers and textures a frame drawn with SETTINGS reads
    // (technique, fins) for this mesh; textures with their mipmaps.
    std::size_t gpuBytes(const RenderSettings& settings) const;

private:
    struct Frame;  // the per-frame uniforms
    Frame frameFor(const Camera& camera, float timeSeconds, const RenderSettings& settings) const;
    void setUniforms(const ShaderProgram& p, const Frame& f) const;
    void setUniforms(const EmulatedGeometryPass& pass, const Frame& f) const;  // its 3 programs
    void drawSkinAndShells(const Frame& f, int shells);
    void drawFins(const Frame& f);
    void drawStrands(const Frame& f);
    void feedCorners();
    long countPrimitives(bool strands,
                         const Frame& f);  // the emulated passes' input primitives, from mesh_

    const StageInfo& stage_;
    StageSources sources_;
    FurScene scene_;
    Mesh mesh_;
    EdgeAdjacency adjacency_;
    std::unique_ptr<MeshBuffers> buffers_;
    std::unique_ptr<Texture2D> colorMap_, pattern_, finMap_;
    std::unique_ptr<ShaderProgram> shells_, fins_, strands_;
    std::unique_ptr<EmulatedGeometryPass> finsEmulated_, strandsEmulated_;
    bool emulate_ = false;
    StrandBudget budget_;
    std::vector<std::filesystem::path> files_;
    std::vector<OpenTodo> todos_;
    int meshShown_ = 0;             // RenderSettings::furMesh of the mesh in buffers_
    MeshPlacement placement_;       // where the scene's OBJ model went (sceneNote)
    glm::vec3 boundsCentre_{0.0f};  // the mesh's bounding sphere, object space
    float boundsRadius_ = 0.0f;
};

}  // namespace raylab
