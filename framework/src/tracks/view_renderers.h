#pragma once
// The frames `raylab check` and grading compare: one renderer of the stage's
// track per scene the views of a stage use (most views use the stage's
// scene; some name another), built when first needed, drawing into float
// targets so that a NaN is seen rather than turned black.
#include "check_report.h"
#include "json_reader.h"
#include "scene_transform.h"
#include "stage_catalog.h"
#include "stage_sources.h"
#include "track_renderer.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace raylab {

// The switches a check view is drawn with.
RenderSettings settingsOf(const CheckView& view);

class ViewRenderers {
public:
    // sceneOverride: a scene file for every view (--scene), or empty.
    // transform: every view's scene and camera resized and moved
    // (scene_transform.h; ray-tracing stages).
    ViewRenderers(const StageInfo& stage, StageSources sources, std::string sceneOverride,
                  int width, int height, SceneTransform transform = {});

    // Throws what the track's renderer throws (a bad scene, a shader error).
    TrackRenderer& forView(const CheckView& view);

    // The scene file VIEW is drawn in.
    std::filesystem::path sceneFileOf(const CheckView& view) const;

    // VIEW drawn with its camera, time and settings, read back to 8 bits
    // (imageFromFloats); *NONFINITE counts NaN/Inf pixels and *TODOPIXELS
    // the pixels that reached a TODO stub (as the shader marked them), when given.
    Image render(const CheckView& view, long* nonFinite = nullptr, long* todoPixels = nullptr);

    // The count check NAME for VIEW (track_renderer.h).
    CountResult countCheck(const std::string& name, const CheckView& view);

private:
    // VIEW's camera: its pose, or its scene file's camera.
    Camera cameraOf(const CheckView& view);

    const StageInfo& stage_;
    StageSources sources_;
    std::string sceneOverride_;
    int width_, height_;
    SceneTransform transform_;
    std::map<std::string, std::unique_ptr<TrackRenderer>> byScene_;
    std::map<std::string, SceneCamera> sceneCameras_;
};

// A count check over several views: how many of the views it applies to agree.
CountOutcome runCountCheck(ViewRenderers& renderers, const std::string& name,
                           const std::vector<CheckView>& views);

}  // namespace raylab
