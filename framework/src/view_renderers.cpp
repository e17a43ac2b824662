#include "view_renderers.h"

#include "paths.h"

namespace raylab {

ViewRenderers::ViewRenderers(const StageInfo& stage, StageSources sources, Scene defaultScene, std::string sceneOverride, int width,
                             int height, PixelFormat format)
    : stage_(stage), sources_(std::move(sources)), defaultScene_(std::move(defaultScene)), sceneOverride_(std::move(sceneOverride)),
      width_(width), height_(height), format_(format) {}

StageRenderer& ViewRenderers::forView(const CheckView& view) {
    const std::string key = sceneOverride_.empty() ? view.scene : "";  // an override puts every view in its scene
    auto it = byScene_.find(key);
    if (it != byScene_.end()) return *it->second;
    Scene scene = key.empty() ? defaultScene_ : loadScene(projectRoot() / "assets" / "scenes" / key);
    auto renderer = std::make_unique<StageRenderer>(stage_, sources_, scene, width_, height_);
    if (format_ != PixelFormat::Rgba8) renderer->resize(width_, height_, format_);
    return *byScene_.emplace(key, std::move(renderer)).first->second;
}

} // namespace raylab
