#pragma once
// One pixel's path as the student's own shader takes it: a debug build of
// the ray tracer's fragment shader that records each findClosest() call -
// every ray it traces, bounces and shadow rays alike - for the page's
// "Trace a pixel" (in the words of `raylab trace`). Students need not read
// this file.
//
// The build renames each call site `findClosest(ray, hit)` to a recorder
// that calls findClosest and, on the call numbered uTraceRecord (1, 2, ...),
// keeps the ray, the hit, the call site and - where the calling function
// keeps the guided lab's `PendingRay current` and `int stackSize` - the
// ray's weight, depth and the stack's size. The stage's main() runs as
// written, renamed; the new main() writes, for uTraceRecord 0, the pixel's
// colour and how many calls there were, else that call's record:
//   location 0: origin.xyz, call site     location 1: dir.xyz, object id (-1: none)
//   location 2: t (-1: none), weight.rgb (-1: not kept)
//   location 3: stack size, depth (-1: not kept), hit (1/0), 0
// Lines keep their origin: a compile error still names the student's line.
#include "shader_source.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace raylab {

// Where a recorded call was made.
struct TraceCallSite {
    std::string function;  // the calling function ("trace", "lightVisible")
    SourceLine where;      // its file and line
};

struct TraceRecording {
    ShaderSource fragment;
    std::vector<TraceCallSite> sites;  // by the site number a record holds
};

// The recorded rays, one line each, then how many and the pixel's colour,
// in the words of `raylab trace`. SUMMARY: what uTraceRecord 0 wrote;
// RECORDS: 16 floats per call (locations 0..3 above). SCALE and OFFSET: the
// frame the shaders drew in (scene_transform.h), undone for people.
std::string formatTracedPath(const std::vector<TraceCallSite>& sites,
                             const std::vector<float>& summary, const std::vector<float>& records,
                             double scale, glm::dvec3 offset);

// FRAGMENT: a ray-tracing stage's assembled fragment shader. Throws Error
// when it has no findClosest() definition or calls to record.
TraceRecording recordTrace(const ShaderSource& fragment);

}  // namespace raylab
