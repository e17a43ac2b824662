#include "view_renderers.h"

#include "count_tables.h"
#include "function_tables.h"

#include "json_reader.h"
#include "stage_renderer.h"
#include "stage_setup.h"
#include "track_registry.h"

namespace raylab {

ViewRenderers::ViewRenderers(const StageInfo& stage, StageSources sources,
                             std::string sceneOverride, int width, int height,
                             SceneTransform transform)
    : stage_(stage), sources_(std::move(sources)), sceneOverride_(std::move(sceneOverride)),
      width_(width), height_(height), transform_(transform) {}

std::filesystem::path ViewRenderers::sceneFileOf(const CheckView& view) const {
    if (!sceneOverride_.empty()) return sceneOverride_;  // an override puts every view in its scene
    return stage_.sceneFileOf(view);
}

TrackRenderer& ViewRenderers::forView(const CheckView& view) {
    const std::string key = sceneFileOf(view).string();
    auto it = byScene_.find(key);
    if (it != byScene_.end()) return *it->second;
    std::unique_ptr<TrackRenderer> renderer;
    if (transform_.identity())
        renderer = makeTrackRenderer(stage_, sources_, key, width_, height_,
                                     PixelFormat::Rgba32FWithTodoMarks, RendererUse::Generic);
    else
        renderer = std::make_unique<StageRenderer>(
            stage_, sources_, transformScene(loadScene(key), transform_), width_, height_,
            PixelFormat::Rgba32FWithTodoMarks);
    return *byScene_.emplace(key, std::move(renderer)).first->second;
}

RenderSettings settingsOf(const CheckView& view) {
    RenderSettings s{view.shadows, view.maxDepth, view.glow, view.normalMaps, view.colorMode};
    s.shells = view.shells;
    s.fins = view.fins;
    s.furTechnique = view.furTechnique;
    return s;
}

Camera ViewRenderers::cameraOf(const CheckView& view) {
    const std::string key = sceneFileOf(view).string();
    auto it = sceneCameras_.find(key);  // each scene file's camera is read once
    if (it == sceneCameras_.end()) it = sceneCameras_.emplace(key, loadSceneCamera(key)).first;
    return Camera(transformPose(view.pose ? *view.pose : it->second.pose, transform_),
                  it->second.fovYDeg);
}

Image ViewRenderers::render(const CheckView& view, long* nonFinite, long* todoPixels) {
    TrackRenderer& r = forView(view);
    r.render(cameraOf(view), view.time, settingsOf(view));
    if (todoPixels) *todoPixels = r.todoPixels();
    return imageFromFloats(r.readFloats(), r.width(), r.height(), nonFinite);
}

CountResult ViewRenderers::countCheck(const std::string& name, const CheckView& view) {
    TrackRenderer& r = forView(view);
    CountResult result = r.countCheck(name, cameraOf(view), view.time, settingsOf(view));
#ifdef RAYLAB_STUDENT_BUILD
    // A student repository holds no reference of the count: its tables do.
    if (result.applies && result.measuredOnly)
        result =
            judgedByTable(countTablesAsData(), kTablesAsData, stage_.id, name, view.name, result);
#endif
    return result;
}

CountOutcome runCountCheck(ViewRenderers& renderers, const std::string& name,
                           const std::vector<CheckView>& views) {
    CountOutcome out;
    out.name = name;
    for (const CheckView& view : views) {
        CountResult r = renderers.countCheck(name, view);
        if (r.applies) tallyCount(out, view.name, r.passed, r.detail);
    }
    return out;
}

}  // namespace raylab
