#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "debug_views.h"
#include "error.h"
#include "paths.h"
#ifndef RAYLAB_STUDENT_BUILD
#include "reference_tracer.h"
#endif
#include "track_registry.h"

#include <cstdio>
#include <cstring>

namespace raylab {

namespace {
// Returns true for a .pfm file, false for .png.
bool checkOutputFile(const std::filesystem::path& out) {
    if (out.empty()) throw Error("--out FILE.png or FILE.pfm is required");
    if (out.extension() != ".png" && out.extension() != ".pfm")
        throw Error("--out '" + out.string() +
                    "': the file name must end in .png (a picture) or .pfm (raw floats)");
    std::error_code ec;
    std::filesystem::path dir = out.parent_path().empty() ? "." : out.parent_path();
    if (!std::filesystem::is_directory(dir, ec))
        throw Error("--out '" + out.string() + "': folder " + dir.string() + " does not exist");
    return out.extension() == ".pfm";
}

void reportSceneNote(const TrackRenderer& renderer) {
    const std::string note = renderer.sceneNote();
    if (!note.empty()) std::printf("raylab: %s\n", note.c_str());
}

// A picture of one colour is written, but said to be one: nothing was drawn
// over the background (a vertex shader that puts every vertex at NaN, a
// model far outside the view...). Facts only: the cause is the student's to
// find, `raylab check` localises it.
void reportOneColour(const Image& picture) {
    if (picture.rgba.size() < 4) return;
    for (std::size_t i = 4; i < picture.rgba.size(); i += 4)
        if (std::memcmp(&picture.rgba[i], &picture.rgba[0], 3) != 0) return;
    std::fprintf(stderr,
                 "raylab: note: every pixel of the picture is (%d, %d, %d): nothing was drawn in "
                 "front of the background (raylab check runs each function on its own)\n",
                 picture.rgba[0], picture.rgba[1], picture.rgba[2]);
}

// The frame drawn as `raylab render` always drew it (8-bit colour).
int renderColorPng(const StageSetup& setup, const RenderOptions& render) {
    auto context = createHeadlessContext(render.backend);
    auto renderer = makeTrackRenderer(setup, setup.size.width, setup.size.height,
                                      PixelFormat::Rgba8, RendererUse::Generic);
    reportOpenTodos(renderer->openTodos());
    reportSceneNote(*renderer);
    renderer->render(setup.camera, setup.time, setup.settings);
    const Image picture = renderer->read();
    writePngAtomic(picture, render.outFile);
    reportOneColour(picture);
    std::printf("raylab: wrote %s (%dx%d, stage %s, %s, %s backend)\n", render.outFile.c_str(),
                setup.size.width, setup.size.height, setup.stage->id.c_str(),
                setup.sources.label.c_str(), context->backendName().c_str());
    return 0;
}

// A view drawn by the stage's shaders on the GPU; *SOURCE says by what.
ViewData gpuView(DebugView view, const StageSetup& setup, Backend backend, std::string* source) {
    auto context = createHeadlessContext(backend);
    const int w = setup.size.width, h = setup.size.height;
    std::vector<float> rgba;
    if (view == DebugView::Color) {
        auto renderer = makeTrackRenderer(setup, w, h, PixelFormat::Rgba32F, RendererUse::Generic);
        reportOpenTodos(renderer->openTodos());
        reportSceneNote(*renderer);
        renderer->render(setup.camera, setup.time, setup.settings);
        rgba = renderer->readFloats();
    } else {
        requireRayTracingStage(*setup.stage, std::string("--view ") + debugViewName(view));
        GpuView gv = view == DebugView::Depth    ? GpuView::Depth
                     : view == DebugView::Normal ? GpuView::Normal
                                                 : GpuView::Id;
        GpuViewRenderer renderer(gv, *setup.stage, setup.sources, setup.scene, w, h);
        reportOpenTodos(renderer.openTodos());
        renderer.render(setup.camera, setup.time, setup.settings);
        rgba = renderer.readFloats();
    }
    *source = setup.sources.label + ", " + context->backendName() + " backend";
    return viewFromGpu(view, rgba, w, h);
}

#ifndef RAYLAB_STUDENT_BUILD  // no reference tracer in a student repository
ViewData referenceView(DebugView view, const StageSetup& setup, std::string* source) {
    requireRayTracingStage(*setup.stage, "the reference tracer (--reference)");
    ReferenceTracer tracer(setup.scene, ReferenceFeatures::forStage(*setup.stage), setup.time,
                           setup.settings);
    std::vector<ReferenceSample> samples =
        tracer.traceImage(setup.camera, setup.size.width, setup.size.height);
    *source = "reference tracer";
    return viewFromReference(view, samples, setup.size.width, setup.size.height);
}
#endif

}  // namespace

int cmdRender(const StageOptions& options, const RenderOptions& render) {
    // Every input is checked before anything is drawn or written.
    const DebugView view = parseDebugView(render.view);
    const bool pfm = checkOutputFile(render.outFile);
#ifdef RAYLAB_STUDENT_BUILD
    if (render.reference || viewNeedsReference(view))
        throw Error(std::string(render.reference ? "--reference" : "--view ") +
                    (render.reference ? "" : debugViewName(view)) +
                    ": the CPU reference tracer draws the solution, which a student repository "
                    "does not hold");
#endif
    if (viewNeedsReference(view) && !render.reference)
        throw Error(std::string("--view ") + debugViewName(view) +
                    " needs --reference (the GPU shaders do not count rays)");
    StageSetup setup = resolveStageOptions(options);
    if (view == DebugView::Color && !pfm && !render.reference) return renderColorPng(setup, render);

    std::string source;
#ifdef RAYLAB_STUDENT_BUILD
    ViewData data = gpuView(view, setup, render.backend, &source);
#else
    ViewData data = render.reference ? referenceView(view, setup, &source)
                                     : gpuView(view, setup, render.backend, &source);
#endif
    std::string mapping;
    if (pfm) {
        writePfmAtomic(data.values, render.outFile);
        mapping = std::string(data.values.channels == 3 ? "3" : "1") + " float" +
                  (data.values.channels == 3 ? "s" : "") + " per pixel: " + pfmDescription(data);
    } else {
        writePngAtomic(viewToPng(data, &mapping), render.outFile);
    }
    std::printf("raylab: wrote %s (%s view, %dx%d, stage %s, %s): %s\n", render.outFile.c_str(),
                debugViewName(view), setup.size.width, setup.size.height, setup.stage->id.c_str(),
                source.c_str(), mapping.c_str());
    return 0;
}

Command renderCommand() {
    return {"render", "render one frame (or a debug view of it) headless to a PNG or PFM file",
            [](CLI::App& cmd) {
                auto stage = std::make_shared<StageOptions>();
                auto render = std::make_shared<RenderOptions>();
                stage->size = "800x600";
                CLI::Option* lab = addStageOptions(cmd, *stage, true);
                cmd.add_option("--out", render->outFile,
                               "output file: .png (a picture) or .pfm (raw floats)")
                    ->required();
                auto backend = std::make_shared<BackendOption>(cmd);
#ifdef RAYLAB_STUDENT_BUILD
                cmd.add_option("--view", render->view, "color, depth, normal, id")
                    ->capture_default_str();
                cmd.add_flag("--reference", render->reference)->group("");  // refused below
#else
                cmd.add_option("--view", render->view,
                               "color, depth, normal, id; with --reference also bounces, stack")
                    ->capture_default_str();
                cmd.add_flag("--reference", render->reference,
                             "draw with the CPU reference tracer instead of the GPU");
#endif
                return std::function<int()>([=] {
                    render->backend = backend->resolve();
                    stage->labGiven = lab->count() > 0;
                    return cmdRender(*stage, *render);
                });
            }};
}

}  // namespace raylab
