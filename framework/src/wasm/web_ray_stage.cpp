#include "web_ray_stage.h"

#include "bvh_boxes.h"
#include "error.h"
#include "eye_cells.h"
#include "gpu_values.h"
#include "light_buffer.h"
#include "paths.h"
#include "shader_constants.h"
#include "shader_source.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

StageSources sourcesFor(const StageInfo& stage, const std::string& lab) {
    return lab.empty() ? solutionSources(stage) : labSources(stage, lab);
}

}  // namespace

WebRayStage::WebRayStage(const WebRayRequest& r)
    : stage_(&findStage(r.stage)), sources_(sourcesFor(*stage_, r.lab)) {
    if (stage_->track != "raytrace")
        throw Error("stage " + stage_->id + " is not a ray-tracing stage");
    if (!stage_->program.geometry.empty())
        throw Error(displayPath(stage_->folder() / "stage.json") +
                    ": program.geometry: the ray tracer's renderer takes no geometry shader");
    const Scene read =
        loadScene(r.scene.empty() ? projectRoot() / "assets" / "scenes" / stage_->scene
                                  : std::filesystem::path(r.scene));
    fileCamera_ = read.camera;
    frame_ = sceneFrame(read);
    scene_ = transformScene(read, frame_);
    checkSceneFits(*stage_, scene_);
    // The page always compiles the program specialised to its scene: the
    // generic one keeps the scene in uniform arrays that can pass WebGL 2's
    // guaranteed 224 vectors.
    variant_ = ShaderVariant::fastestFor(scene_);
    if (r.bvh >= 0) variant_.bvh = r.bvh == 1;
    if (r.demoLevers) {
        if (!r.lab.empty())
            throw Error("the demo's levers replace files students write: only for the solution");
        variant_.useDemoLevers();
    }
    variant_.webGl2 = true;
    variant_.maxBlockBytes = r.maxBlockBytes;
    variant_.todoMarks = r.todoMarks;
    if (r.maxBlockBytes > 0 && int(scene_.spheres.size()) > r.maxBlockBytes / kSphereBlockStride)
        throw Error(scene_.file + ": spheres: " + std::to_string(scene_.spheres.size()) +
                    " spheres, but this browser's uniform blocks hold at most " +
                    std::to_string(r.maxBlockBytes / kSphereBlockStride) +
                    " (MAX_UNIFORM_BLOCK_SIZE " + std::to_string(r.maxBlockBytes) + " bytes, " +
                    std::to_string(kSphereBlockStride) + " per sphere)");
    view_ = parseDebugView(r.view);
    if (viewNeedsReference(view_))
        throw Error(std::string("the ") + debugViewName(view_) +
                    " view counts the reference tracer's rays: raylab render --view " +
                    debugViewName(view_) + " --reference draws it natively");
    std::string entry;
    if (view_ != DebugView::Color) {
        // view_main.frag around the stage's own files (debug_views.h natively).
        viewStage_ = *stage_;
        for (const std::string& d : gpuViewDefines(GpuView(int(view_)), stage_->has("surface_at")))
            viewStage_.extraDefines.push_back(d);
        stage_ = &viewStage_;
        entry = kViewFragmentEntry;
    }
    programs_ = assembleStagePrograms(*stage_, sources_, scene_, variant_, entry);
    if (r.trace) {
        TraceRecording recording = recordTrace(programs_.fragment);
        programs_.fragment = std::move(recording.fragment);
        traceSites_ = std::move(recording.sites);
    }
    todos_ = findOpenTodos(programs_.fragment);
    const std::string& text = programs_.fragment.text;
    auto reads = [&](const char* uniform) { return text.find(uniform) != std::string::npos; };
    // The buffers only for a program that reads them (as natively).
    if (variant_.bvh && reads("uBvhNodes")) {
        const Bvh bvh = buildBvh(scene_, 2, BvhObjects::SpheresAndMeshes);
        bvhNodes = packedBvhNodes(bvh);
        appendBvhBoxTexels(bvh, bvhNodes);  // the eye-cells walk's one-texel nodes (bvh_boxes.h)
        bvhItems.assign(bvh.items.begin(), bvh.items.end());
        treeItemCount_ = bvhItems.size();
        if (reads("uEyeCells")) eyeCube_.emplace(kEyeCellResolution);
    }
    if (reads("uMeshCorners")) {
        meshCorners = meshCornerTexels(scene_);
        meshMaterials = meshTriangleMaterials(scene_);
    }
    if (reads("uLightCells")) {
        lightBuffer = buildLightBuffer(scene_);
        lightCells = lightCellTexels(lightBuffer);
        lightItems.assign(lightBuffer.items.begin(), lightBuffer.items.end());
        lightBuffer.cells.clear();  // kept for its uniforms only
        lightBuffer.items.clear();
    }
}

std::vector<std::string> WebRayStage::levers() const {
    std::vector<std::string> on;
    const std::string& text = programs_.fragment.text;
    auto has = [&](const char* define) {
        return text.find(std::string("#define ") + define) != std::string::npos;
    };
    if (has("RAYLAB_BVH")) on.push_back(usesEyeCells() ? "BVH, eye cells" : "BVH");
    if (has("RAYLAB_LIGHT_BUFFER")) on.push_back("light buffer");
    if (has("RAYLAB_TORI_HIDDEN_FROM_LIGHTS")) on.push_back("tori hidden from the lights");
    if (has("RAYLAB_SHARED_WORK")) on.push_back("shared work");
    if (has("RAYLAB_WEIGHT_CUT")) on.push_back("weight cut");
    return on;
}

std::vector<float> WebRayStage::sphereCentres(float t) const {
    std::vector<float> out(4 * std::max<std::size_t>(1, scene_.spheres.size()), 0.0f);
    for (std::size_t i = 0; i < scene_.spheres.size(); ++i) {
        const Sphere& s = scene_.spheres[i];
        const glm::vec4 c = gpuSphere(s, t);  // as the native renderer's blocks hold it
        std::copy_n(&c.x, 4, &out[4 * i]);
    }
    return out;
}

std::vector<float> WebRayStage::torusToLocal(float t) const {
    std::vector<float> out;
    for (const Torus& torus : scene_.tori) {
        const glm::mat3 m = raylab::torusToLocal(torus.axisAt(t));
        for (int c = 0; c < 3; ++c) out.insert(out.end(), {m[c].x, m[c].y, m[c].z});
    }
    return out;
}

bool WebRayStage::moveEye(glm::vec3 eye) {
    if (!eyeCube_ || (eyeBuilt_ && eye == eyeCellsCentre_)) return false;
    const EyeCells built = buildEyeCells(scene_, eye, *eyeCube_);
    bvhItems.resize(treeItemCount_);
    const int base = int(bvhItems.size());
    bvhItems.insert(bvhItems.end(), built.items.begin(), built.items.end());
    eyeCells = eyeCellTexels(built, base);
    eyeCellsCentre_ = eye;
    eyeBuilt_ = true;
    return true;
}

Image WebRayStage::viewPicture(const std::vector<float>& bottomUp, int width, int height,
                               std::string* mapping) const {
    const std::size_t row = std::size_t(width) * 4;
    if (width <= 0 || height <= 0 || bottomUp.size() != row * std::size_t(height))
        throw Error("viewPicture: " + std::to_string(bottomUp.size()) + " floats for " +
                    std::to_string(width) + "x" + std::to_string(height));
    std::vector<float> rows(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row), row,
                    rows.begin() + std::ptrdiff_t(std::size_t(y) * row));
    // The shaders measure depth in their frame; people read the file's units
    // (GpuViewRenderer::readFloats).
    if (view_ == DebugView::Depth && frame_.scale != 1.0)
        for (std::size_t i = 0; i < rows.size(); i += 4)
            rows[i] = float(double(rows[i]) / frame_.scale);
    return viewToPng(viewFromGpu(view_, rows, width, height), mapping);
}

std::string WebRayStage::traceReport(const std::vector<float>& summary,
                                     const std::vector<float>& records, int x, int y, int width,
                                     int height) const {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    return "your shader's path at pixel " + std::to_string(x) + "," + std::to_string(y) +
           " (0,0 top left): stage " + stage_->id + ", scene " + scene_.file + ", " + size +
           "; each ray findClosest() traced, in order:\n" +
           formatTracedPath(traceSites_, summary, records, frame_.scale, frame_.offset) +
           "The reference's path beside yours is native's: raylab trace --stage " + stage_->id +
           " --pixel " + std::to_string(x) + "," + std::to_string(y) + " --size " + size +
           " (the reference tracer is every stage's answer in C++, so the page has none).\n";
}

}  // namespace raylab
