#pragma once
// The debug views on the GPU, natively (`raylab render --view ...`, `raylab
// rays`): the stage's own shader files built from view_main.frag
// (core/view_pictures.h says what each view holds and draws its picture),
// and every view from the CPU reference tracer (with --reference; bounces
// and stack exist only there, since the GPU shaders do not count rays).
#include "stage_renderer.h"
#include "view_pictures.h"

#include <vector>

namespace raylab {

struct ReferenceSample;

// A stage's program built from view_main.frag instead of main.frag, with
// every uniform StageRenderer uploads. Needs a current GL context; throws
// Error or ShaderError like StageRenderer.
class GpuViewRenderer {
public:
    GpuViewRenderer(GpuView view, const StageInfo& stage, StageSources sources, Scene scene,
                    int width, int height, ShaderVariant variant = {});
    GpuViewRenderer(const GpuViewRenderer&) = delete;
    GpuViewRenderer& operator=(const GpuViewRenderer&) = delete;

    void render(const Camera& camera, float timeSeconds, const RenderSettings& settings = {}) {
        renderer_.render(camera, timeSeconds, settings);
    }
    // RGBA, top row first; depths in the scene's own units (the shaders
    // measure them in the renderer's frame).
    std::vector<float> readFloats() const;
    const std::vector<OpenTodo>& openTodos() const { return renderer_.openTodos(); }

private:
    GpuView view_;
    StageInfo stage_;  // the stage plus the view's #defines; renderer_ refers to it
    StageRenderer renderer_;
};

// The reference tracer's samples (row-major, top row first) to ViewData.
ViewData viewFromReference(DebugView view, const std::vector<ReferenceSample>& samples, int width,
                           int height);

}  // namespace raylab
