#pragma once
// Per-pixel numbers about a frame, and their pictures for people: the
// debug views of `raylab render --view ...` and of the page's View menu.
//
//   color    the frame (as `raylab render` draws it; PFM: linear, unclamped)
//   depth    hit distance t along the primary ray (0 where it hit nothing)
//   normal   unit outward normal at the primary hit (0 where it hit nothing)
//   id       the object hit, kind * 2^20 + index as in scene_objects.glsl (-1: nothing)
//   bounces  rays traced for the pixel (primary, reflected, refracted; reference only)
//   stack    the most rays waiting on the stack at once (reference only)
//
// The GPU views (depth, normal, id) run the stage's own shader files through
// framework/shaders/view_main.frag (raytrace/debug_views.h natively, the
// page's core in the browser); this file turns what they wrote into
// pictures, the same way on both.
#include "image.h"
#include "pfm.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

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

// The entry fragment shader of the GPU views (framework/shaders/).
inline constexpr const char* kViewFragmentEntry = "view_main.frag";

// The #defines view_main.frag needs for VIEW; SURFACEAT: the stage has
// surfaceAt() (its stage.json says "surface_at").
std::vector<std::string> gpuViewDefines(GpuView view, bool surfaceAt);

// RGBA floats of a GPU view (or of a Rgba32F colour frame for Color) to ViewData.
ViewData viewFromGpu(DebugView view, const std::vector<float>& rgba, int width, int height);

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
