#pragma once
// Which renderer draws a stage: the one of its track (stage.json "track").
// A new track adds a row to kTracks in track_registry.cpp; nothing else
// branches on the track, except the ray tracer's own tools (debug views,
// reference tracer, ray dumps), which say so when given another track's stage.
#include "pixel_format.h"
#include "stage_catalog.h"
#include "stage_setup.h"
#include "stage_sources.h"
#include "track_renderer.h"

#include <filesystem>
#include <memory>

namespace raylab {

// How a renderer is used. The window and the demo want the fastest correct
// program for the scene; the checks and grading draw with the stage's
// generic program, the one students write.
enum class RendererUse { Fastest, Generic };

// The renderer of STAGE's track for the scene file SCENEFILE. Needs a
// current GL context. Throws Error (no renderer for the track, a bad scene)
// or ShaderError.
std::unique_ptr<TrackRenderer> makeTrackRenderer(const StageInfo& stage,
                                                 const StageSources& sources,
                                                 const std::filesystem::path& sceneFile, int width,
                                                 int height, PixelFormat format, RendererUse use);

// The same for a resolved command line (the scene is already loaded).
std::unique_ptr<TrackRenderer> makeTrackRenderer(const StageSetup& setup, int width, int height,
                                                 PixelFormat format = PixelFormat::Rgba8,
                                                 RendererUse use = RendererUse::Fastest);

// Reads SCENEFILE as STAGE's track reads scenes, so that a bad file stops a
// command before any window or context exists. Throws Error.
void checkTrackScene(const StageInfo& stage, const std::filesystem::path& sceneFile);

// Throws Error("stage ID is on the TRACK track: WHAT draws ray-tracing stages
// only") unless STAGE is a ray-tracing stage.
void requireRayTracingStage(const StageInfo& stage, const std::string& what);

}  // namespace raylab
