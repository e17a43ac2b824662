#include "view_renderers.h"

#include "paths.h"
#include "stage_setup.h"

namespace raylab {

ViewRenderers::ViewRenderers(const StageInfo& stage, StageSources sources, Scene defaultScene,
                             std::string sceneOverride, int width, int height)
    : stage_(stage), sources_(std::move(sources)), defaultScene_(std::move(defaultScene)),
      sceneOverride_(std::move(sceneOverride)), width_(width), height_(height) {}

StageRenderer& ViewRenderers::forView(const CheckView& view) {
    const std::string key =
        sceneOverride_.empty() ? view.scene : "";  // an override puts every view in its scene
    auto it = byScene_.find(key);
    if (it != byScene_.end()) return *it->second;
    Scene scene =
        key.empty() ? defaultScene_ : loadScene(projectRoot() / "assets" / "scenes" / key);
    auto renderer = std::make_unique<StageRenderer>(stage_, sources_, scene, width_, height_,
                                                    PixelFormat::Rgba32F);
    return *byScene_.emplace(key, std::move(renderer)).first->second;
}

RenderSettings settingsOf(const CheckView& view) {
    return RenderSettings{view.shadows, view.maxDepth, view.glow, view.normalMaps, view.colorMode};
}

Image ViewRenderers::render(const CheckView& view, long* nonFinite) {
    StageRenderer& r = forView(view);
    r.render(cameraFor(view.pose, r.scene()), view.time, settingsOf(view));
    return imageFromFloats(r.target().readFloats(), r.target().width(), r.target().height(),
                           nonFinite);
}

}  // namespace raylab
