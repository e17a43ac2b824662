#pragma once
// The frames `raylab check` and grading compare: one StageRenderer per scene
// the views of a stage use (most views use the stage's scene; stage 08's also
// use pro.json), built when first needed, drawing into float targets so that
// a NaN is seen rather than turned black.
#include "stage_renderer.h"

#include <map>
#include <memory>
#include <string>

namespace raylab {

// The switches a check view is drawn with.
RenderSettings settingsOf(const CheckView& view);

class ViewRenderers {
public:
    // sceneOverride: a scene file for every view (--scene), or empty.
    ViewRenderers(const StageInfo& stage, StageSources sources, Scene defaultScene,
                  std::string sceneOverride, int width, int height);

    // Throws what StageRenderer throws (a bad scene, a shader error).
    StageRenderer& forView(const CheckView& view);

    // VIEW drawn with its camera, time and settings, read back to 8 bits
    // (imageFromFloats); *NONFINITE counts NaN/Inf pixels when given.
    Image render(const CheckView& view, long* nonFinite = nullptr);

private:
    const StageInfo& stage_;
    StageSources sources_;
    Scene defaultScene_;
    std::string sceneOverride_;
    int width_, height_;
    std::map<std::string, std::unique_ptr<StageRenderer>> byScene_;
};

}  // namespace raylab
