#pragma once
// The debug views of `raylab render --view ...` and the primary-ray dump of
// `raylab rays`: per-pixel numbers about a frame instead of its colour.
//
//   color    the frame (as `raylab render` draws it; PFM: linear, unclamped)
//   depth    hit distance t along the primary ray (0 where it hit nothing)
//   normal   unit outward normal at the primary hit (0 where it hit nothing)
//   id       the object hit, kind * 2^20 + index as in scene_objects.glsl (-1: nothing)
//   bounces  rays traced for the pixel (primary, reflected, refracted; reference only)
//   stack    the most rays waiting on the stack at once (reference only)
//
// The GPU views (color, depth, normal, id) run the stage's own shader files:
// framework/shaders/view_main.frag includes the stage's main.frag, renames
// its main() and writes the number into a float render target. With
// --reference every view comes from the CPU reference tracer
// (reference_tracer.h); bounces and stack exist only there, since the GPU
// shaders do not count rays.
#include "image.h"
#include "pfm.h"
#include "stage_renderer.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

struct ReferenceSample;

enum class DebugView { Color, Depth, Normal, Id, Bounces, Stack };

// "color", "depth", ... Throws Error("unknown view 'x' (views: ...)").
DebugView parseDebugView(const std::string& name);
const char* debugViewName(DebugView view);
// Bounces and stack: only the reference tracer counts rays.
bool viewNeedsReference(DebugView view);

// One view of one frame, ready to be written.
struct ViewData {
    DebugView view = DebugView::Color;
    FloatImage values;  // 3 channels (color, normal) or 1; top row first; misses as above
    std::vector<std::uint8_t> hit;       // per pixel: the primary ray hit an object
    std::vector<std::uint8_t> overflow;  // per pixel: a refracted ray was dropped (reference only)
};

// What view_main.frag writes (its RAYLAB_VIEW values).
enum class GpuView { Depth = 1, Normal = 2, Id = 3, Rays = 4 };

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

// The entry fragment shader of the GPU views (framework/shaders/).
inline constexpr const char* kViewFragmentEntry = "view_main.frag";

// RGBA floats of a GPU view (or of a Rgba32F colour frame for Color) to ViewData.
ViewData viewFromGpu(DebugView view, const std::vector<float>& rgba, int width, int height);
// The reference tracer's samples (row-major, top row first) to ViewData.
ViewData viewFromReference(DebugView view, const std::vector<ReferenceSample>& samples, int width,
                           int height);

// The picture of a view for people: colour clamped to 8 bits; depth grey,
// near bright, scaled to the image's range, misses black; normal 0.5 + 0.5 n,
// misses black; id a colour per object (a hash of the id), misses black;
// bounces and stack a blue..yellow ramp over the image's range, overflow
// pixels pure red. *MAPPING gets a short phrase saying what was mapped how
// ("depth 2.31..41.7 mapped to white..grey, misses black").
Image viewToPng(const ViewData& data, std::string* mapping);
// What the PFM holds, in the same kind of phrase.
std::string pfmDescription(const ViewData& data);

// The colour the id view gives object ID (never black, never pure red).
void idColor(int id, std::uint8_t rgb[3]);

}  // namespace raylab
