#pragma once
// Renders one stage of the tracer: builds its shader program, uploads the
// camera and the scene, and draws the canvas into an off-screen framebuffer.
// Used the same way by the window, headless rendering and the checks.
#include "camera.h"
#include "canvas.h"
#include "framebuffer.h"
#include "render_settings.h"
#include "scene.h"
#include "scene_transform.h"
#include "shader_program.h"
#include "stage_catalog.h"
#include "stage_programs.h"
#include "stage_sources.h"
#include "target_renderer.h"
#include "texture.h"

#include "bvh_buffers.h"
#include "eye_cell_buffers.h"
#include "light_buffer_buffers.h"
#include "scene_mesh_buffers.h"
#include "sphere_blocks.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace raylab {

// The ray-tracing track's renderer: a full-screen canvas whose fragment
// shader traces the scene.
class StageRenderer : public TargetRenderer {
public:
    // Needs a current GL context. Throws Error (bad scene, missing file) or
    // ShaderError (compile/link error, mapped to file:line).
    // FRAGMENTENTRY: the entry fragment shader; empty for the stage's own
    // (another one, e.g. the debug views' view_main.frag, gets the same uniforms).
    StageRenderer(const StageInfo& stage, StageSources sources, Scene scene, int width, int height,
                  PixelFormat format = PixelFormat::Rgba8, std::string fragmentEntry = "",
                  ShaderVariant variant = {});

    void render(const Camera& camera, float timeSeconds,
                const RenderSettings& settings = {}) override;
    // The scene as the shaders see it: resized and moved into the standard
    // frame (sceneFrame, scene_transform.h); for RayLab's own scenes the
    // scene as given.
    const Scene& scene() const { return scene_; }
    const SceneTransform& frame() const { return frame_; }
    const ShaderVariant& variant() const { return variant_; }

    void rebuild() override;
    // The program's fragment shader rewritten by REWRITE before it is
    // compiled (the trace build, trace_recording.h); rebuilds.
    void setFragmentRewrite(std::function<ShaderSource(const ShaderSource&)> rewrite);
    // Draws the frame into FRAMEBUFFER with the picture's viewport placed at
    // (X, Y), so that a chosen pixel of the picture lands on a chosen pixel
    // of FRAMEBUFFER, with uTraceRecord = RECORD (gpu_trace.h).
    void renderAt(GLuint framebuffer, int x, int y, int record, const Camera& camera,
                  float timeSeconds, const RenderSettings& settings);
    const std::vector<std::filesystem::path>& sourceFiles() const override { return files_; }
    const std::vector<OpenTodo>& openTodos() const override { return todos_; }

private:
    // The static part of the scene (background, materials, lights): uniforms
    // belong to a program, so this runs after every (re)build, not every frame.
    void uploadSceneConstants();
    void uploadStaticShapes();
    // Everything but where the frame goes: the uniforms, textures and buffers, the draw.
    void drawFrame(const Camera& camera, float timeSeconds, const RenderSettings& settings);
    std::function<ShaderSource(const ShaderSource&)> fragmentRewrite_;

    const StageInfo& stage_;
    StageSources sources_;
    SceneTransform frame_;  // from the scene's units to the shaders'
    Scene scene_;
    Canvas canvas_;
    std::unique_ptr<ShaderProgram> program_;
    std::unique_ptr<TextureArray> textures_;
    std::unique_ptr<CubeMap> sky_;
    ShaderVariant variant_;
    std::unique_ptr<BvhBuffers> bvh_;                  // made when the program walks a BVH
    std::unique_ptr<SceneMeshBuffers> meshes_;         // made when the scene has meshes
    std::unique_ptr<LightBufferBuffers> lightBuffer_;  // made when shadow rays use one
    std::unique_ptr<EyeCellBuffers> eyeCells_;         // made when primary rays use them
    bool programUsesEyeCells_ = false;
    std::unique_ptr<SphereBlocks> spheres_;  // the spheres' uniform blocks
    std::vector<std::filesystem::path> files_;
    std::vector<OpenTodo> todos_;
    std::string fragmentEntry_;
};

}  // namespace raylab
