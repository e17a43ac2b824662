#include "track_registry.h"

#include "error.h"
#include "fur_renderer.h"
#include "fur_scene.h"
#include "stage_renderer.h"

namespace raylab {

namespace {

std::unique_ptr<TrackRenderer> rayTracer(const StageInfo& stage, const StageSources& sources,
                                         const Scene* loaded, const std::filesystem::path& file,
                                         int width, int height, PixelFormat format,
                                         RendererUse use) {
    Scene scene = loaded ? *loaded : loadScene(file);
    ShaderVariant variant =
        use == RendererUse::Fastest ? ShaderVariant::fastestFor(scene) : ShaderVariant{};
    // The window showing the solution (`raylab demo`, `raylab run --solution`)
    // may trace as the headless demo does, without the rays too faint to
    // change a pixel and with the shared-work variants; a student's files
    // are never replaced by a variant.
    if (use == RendererUse::Fastest && !sources.lab) variant.useDemoLevers();
    return std::make_unique<StageRenderer>(stage, sources, std::move(scene), width, height, format,
                                           "", variant);
}

std::unique_ptr<TrackRenderer> fur(const StageInfo& stage, const StageSources& sources,
                                   const Scene*, const std::filesystem::path& file, int width,
                                   int height, PixelFormat format, RendererUse) {
    return std::make_unique<FurRenderer>(stage, sources, loadFurScene(file), width, height, format);
}

struct Track {
    const char* name;
    std::unique_ptr<TrackRenderer> (*make)(const StageInfo&, const StageSources&, const Scene*,
                                           const std::filesystem::path&, int, int, PixelFormat,
                                           RendererUse);
    void (*checkScene)(const std::filesystem::path&);
};
constexpr Track kTracks[] = {
    {"raytrace", rayTracer, [](const std::filesystem::path& f) { loadScene(f); }},
    // The mesh too (an OBJ file is only named by the scene): a bad one stops
    // the command before any window, context or output folder exists.
    {"fur", fur, [](const std::filesystem::path& f) { loadFurMesh(loadFurScene(f)); }},
};

const Track& trackOf(const StageInfo& stage) {
    for (const Track& t : kTracks)
        if (stage.track == t.name) return t;
    throw Error("stage " + stage.id + ": no renderer for track '" + stage.track + "'");
}

}  // namespace

std::unique_ptr<TrackRenderer> makeTrackRenderer(const StageInfo& stage,
                                                 const StageSources& sources,
                                                 const std::filesystem::path& sceneFile, int width,
                                                 int height, PixelFormat format, RendererUse use) {
    return trackOf(stage).make(stage, sources, nullptr, sceneFile, width, height, format, use);
}

std::unique_ptr<TrackRenderer> makeTrackRenderer(const StageSetup& setup, int width, int height,
                                                 PixelFormat format, RendererUse use) {
    const Scene* loaded = setup.stage->track == "raytrace" ? &setup.scene : nullptr;
    return trackOf(*setup.stage)
        .make(*setup.stage, setup.sources, loaded, setup.sceneFile, width, height, format, use);
}

void checkTrackScene(const StageInfo& stage, const std::filesystem::path& sceneFile) {
    trackOf(stage).checkScene(sceneFile);
}

void requireRayTracingStage(const StageInfo& stage, const std::string& what) {
    if (stage.track != "raytrace")
        throw Error("stage " + stage.id + " is on the " + stage.track + " track: " + what +
                    " draws ray-tracing stages only");
}

}  // namespace raylab
