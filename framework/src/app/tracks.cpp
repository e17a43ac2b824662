#include "tracks.h"

#include "error.h"
#include "stage_renderer.h"

namespace raylab {

namespace {

std::unique_ptr<TrackRenderer> rayTracer(const StageSetup& setup, int width, int height) {
    return std::make_unique<StageRenderer>(*setup.stage, setup.sources, setup.scene, width, height,
                                           PixelFormat::Rgba8, "",
                                           ShaderVariant::fastestFor(setup.scene));
}

struct Track {
    const char* name;
    std::unique_ptr<TrackRenderer> (*make)(const StageSetup&, int, int);
};
constexpr Track kTracks[] = {
    {"raytrace", rayTracer},
};

}  // namespace

std::unique_ptr<TrackRenderer> makeTrackRenderer(const StageSetup& setup, int width, int height) {
    for (const Track& t : kTracks)
        if (setup.stage->track == t.name) return t.make(setup, width, height);
    throw Error("stage " + setup.stage->id + ": no renderer for track '" + setup.stage->track +
                "'");
}

}  // namespace raylab
