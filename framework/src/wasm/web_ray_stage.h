#pragma once
// A ray-tracing stage as the web page draws it: what the native renderer
// (raytrace/stage_renderer.cpp) prepares on the CPU, with the same code, for
// the page's WebGL 2 calls (web/src/raytrace/stage_renderer.ts). The scene
// read and framed, checked against the stage's limits, the program assembled
// (GLSL ES 3.00, the variant raylab demo or the window would pick), and the
// data its textures and uniform blocks hold. Students need not read this file.
#include "bvh.h"
#include "cell_cube.h"
#include "light_buffer.h"
#include "scene.h"
#include "scene_transform.h"
#include "stage_programs.h"
#include "trace_recording.h"
#include "view_pictures.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

// What the page asks for (web/src/core/core.ts writes it as JSON).
struct WebRayRequest {
    std::string stage;           // id or number
    std::string lab;             // the lab's folder (laid out like labs/); empty: the solution
    std::string scene;           // a scene file; empty: the stage's own
    bool demoLevers = false;     // the demo's levers (solution only), as `raylab demo`
    int bvh = -1;                // 1 or 0: with or without the BVH; -1: the fastest choice
    int maxBlockBytes = 0;       // the browser's MAX_UNIFORM_BLOCK_SIZE
    bool todoMarks = false;      // also mark the pixels that reach a TODO stub (a check's target)
    std::string view = "color";  // a debug view (depth, normal, id): view_main.frag's program
    bool trace = false;  // the debug build that records one pixel's path (trace_recording.h)
};

class WebRayStage {
public:
    // Throws Error with native's messages.
    explicit WebRayStage(const WebRayRequest& request);

    const StageInfo& stage() const { return *stage_; }
    const Scene& scene() const { return scene_; }  // in the shaders' frame
    const SceneTransform& frame() const { return frame_; }
    // The scene file's own camera, in the file's units (the page's camera
    // moves in them; frame().point(eye) is where the shaders see it).
    const CameraPose& fileCamera() const { return fileCamera_; }
    const ShaderVariant& variant() const { return variant_; }
    const StagePrograms& programs() const { return programs_; }
    const std::vector<OpenTodo>& todos() const { return todos_; }
    DebugView view() const { return view_; }
    // With WebRayRequest::trace: the recorded path of pixel (X, Y) (0,0 top
    // left) of a WIDTH x HEIGHT picture, in the words of `raylab trace`.
    // SUMMARY: what uTraceRecord 0 wrote (colour, calls); RECORDS: 16
    // floats per call (locations 0..3, trace_recording.h).
    std::string traceReport(const std::vector<float>& summary, const std::vector<float>& records,
                            int x, int y, int width, int height) const;
    // The picture of a frame of the debug view (RGBA floats the program
    // wrote, rows bottom-up as WebGL reads them), depths in the scene
    // file's units; *MAPPING says what was mapped how (view_pictures.h).
    Image viewPicture(const std::vector<float>& bottomUp, int width, int height,
                      std::string* mapping) const;
    // What the program was compiled with, for the overlay ("BVH", "light buffer", ...).
    std::vector<std::string> levers() const;

    // The spheres' uniform block at time T: (centre, radius) per sphere,
    // at least one entry (the block's declared array).
    std::vector<float> sphereCentres(float t) const;
    // Each torus's world-to-local rotation at time T, column-major 3x3.
    std::vector<float> torusToLocal(float t) const;

    // Filled where the program reads them (empty otherwise).
    std::vector<float> bvhNodes;  // 2 RGBA texels a node (bvh_access.glsl), then bvh_boxes.h's
    std::vector<int> bvhItems;    // the tree's items, then the eye cells' lists
    std::vector<int> lightCells;  // RGBA per cell
    std::vector<int> lightItems;
    LightBuffer lightBuffer;         // its uniforms (resolution, reach, every-object cell)
    std::vector<int> eyeCells;       // RG per cell: (first in bvhItems, count)
    std::vector<float> meshCorners;  // six RGBA texels per mesh triangle (scene_meshes.glsl)
    std::vector<int> meshMaterials;  // per mesh triangle
    bool usesEyeCells() const { return eyeCube_.has_value(); }
    int eyeCellResolution() const { return eyeCube_ ? eyeCube_->resolution() : 0; }
    glm::vec3 eyeCellsCentre() const { return eyeCellsCentre_; }
    // Rebuilds the eye cells for EYE (in the shaders' frame) when it has
    // moved; true when bvhItems and eyeCells changed.
    bool moveEye(glm::vec3 eye);

private:
    const StageInfo* stage_ = nullptr;
    StageInfo viewStage_;  // the stage with a debug view's #defines (stage_ points here then)
    DebugView view_ = DebugView::Color;
    std::vector<TraceCallSite> traceSites_;
    StageSources sources_;
    Scene scene_;
    SceneTransform frame_;
    CameraPose fileCamera_;
    ShaderVariant variant_;
    StagePrograms programs_;
    std::vector<OpenTodo> todos_;
    std::size_t treeItemCount_ = 0;
    std::optional<CellCube> eyeCube_;
    glm::vec3 eyeCellsCentre_{0.0f};
    bool eyeBuilt_ = false;
};

}  // namespace raylab
