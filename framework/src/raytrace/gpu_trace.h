#pragma once
// One pixel's path through the stage's own shader on the GPU, natively
// (`raylab trace`, beside the reference tracer's path): the trace build of
// core/trace_recording.h drawn once per recorded ray for that pixel into a
// one-row float target (the page does the same: web/src/app/pixel_trace.ts).
#include "camera.h"
#include "render_settings.h"
#include "scene.h"
#include "stage_catalog.h"
#include "stage_sources.h"

#include <string>

namespace raylab {

// The rays the shader at SOURCES traced for pixel (X, Y) (0,0 top left) of
// a WIDTH x HEIGHT picture of SCENE, one line each, then how many and the
// pixel's colour (formatTracedPath). Needs a current GL context; throws
// Error or ShaderError (a compile error at the student's file and line).
std::string traceShaderPath(const StageInfo& stage, const StageSources& sources, const Scene& scene,
                            const Camera& camera, float timeSeconds, const RenderSettings& settings,
                            int width, int height, int x, int y);

}  // namespace raylab
