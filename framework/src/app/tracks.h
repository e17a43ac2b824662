#pragma once
// Which renderer draws a stage: the one of its track (stage.json "track").
// A new track adds its renderer here; nothing else branches on the track.
#include "stage_setup.h"
#include "track_renderer.h"

#include <memory>

namespace raylab {

// The renderer of SETUP's stage at WIDTH x HEIGHT, built with the fastest
// correct shader for its scene. Needs a current GL context. Throws Error for
// a track that has no renderer.
std::unique_ptr<TrackRenderer> makeTrackRenderer(const StageSetup& setup, int width, int height);

}  // namespace raylab
