// The page's entry into the core (embind): web/src/core/core.ts is its only
// caller. Requests and small answers are JSON text; arrays of numbers are
// typed arrays (copies: wasm memory may move when it grows). A constructor
// never throws into JavaScript: errors, with native's text, are kept and
// read through error(). Students need not read this file.
#include "error.h"
#include "shader_source.h"
#include "web_ray_stage.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

using emscripten::val;
using nlohmann::json;

namespace raylab {

namespace {

template <typename T>
val typedArray(const char* type, const std::vector<T>& values) {
    return val::global(type).new_(emscripten::typed_memory_view(values.size(), values.data()));
}

json sourceJson(const ShaderSource& s) {
    json origin = json::array();
    for (const SourceLine& l : s.origin) origin.push_back({l.file, l.line});
    return {{"text", s.text}, {"origin", origin}};
}

json vec3Json(glm::vec3 v) { return {v.x, v.y, v.z}; }

// A ray-tracing stage for the page (web_ray_stage.h).
class RayStage {
public:
    explicit RayStage(const std::string& requestJson) {
        try {
            const json r = json::parse(requestJson);
            WebRayRequest q;
            q.stage = r.value("stage", "");
            q.lab = r.value("lab", "");
            q.scene = r.value("scene", "");
            q.demoLevers = r.value("demoLevers", false);
            q.bvh = r.value("bvh", -1);
            q.maxBlockBytes = r.value("maxBlockBytes", 0);
            stage_ = std::make_unique<WebRayStage>(q);
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    std::string error() const { return error_; }

    // Everything but the big arrays, as JSON.
    std::string info() const {
        if (!stage_) return "{}";
        const WebRayStage& s = *stage_;
        const Scene& scene = s.scene();
        json todos = json::array();
        for (const OpenTodo& t : s.todos())
            todos.push_back({{"file", t.file}, {"line", t.line}, {"title", t.title}});
        json textures = json::array(), sky = json::array();
        for (const auto& t : scene.textures) textures.push_back(t.string());
        if (scene.skyBox)
            for (const auto& f : *scene.skyBox) sky.push_back(f.string());
        const CameraPose& cam = s.fileCamera();
        return json{{"stage", s.stage().id},
                    {"sceneFile", scene.file},
                    {"vertex", sourceJson(s.programs().vertex)},
                    {"fragment", sourceJson(s.programs().fragment)},
                    {"todos", todos},
                    {"levers", s.levers()},
                    {"spheres", scene.spheres.size()},
                    {"tori", scene.tori.size()},
                    {"triangles", scene.triangles.size()},
                    {"lights", scene.lights.size()},
                    {"textures", textures},
                    {"skyBox", sky},
                    {"camera",
                     {{"position", vec3Json(cam.position)},
                      {"yaw", cam.yawDeg},
                      {"pitch", cam.pitchDeg},
                      {"fovY", scene.fovYDeg}}},
                    {"lightBuffer",
                     {{"size", s.lightBuffer.resolution},
                      {"everyCell", int(s.lightCells.size() / 4) - 1},
                      {"reach", s.lightBuffer.reach}}},
                    {"eyeCellsSize", s.eyeCellResolution()}}
            .dump();
    }

    // A driver's log with the assembled lines mapped to file:line (native's
    // mapCompilerLog). WHICH: "vertex" or "fragment".
    std::string mapLog(const std::string& log, const std::string& which) const {
        if (!stage_) return log;
        const StagePrograms& p = stage_->programs();
        return mapCompilerLog(log, which == "vertex" ? p.vertex : p.fragment);
    }

    val sphereCentres(float t) const { return typedArray("Float32Array", stage_->sphereCentres(t)); }
    val torusToLocal(float t) const { return typedArray("Float32Array", stage_->torusToLocal(t)); }
    val bvhNodes() const { return typedArray("Float32Array", stage_->bvhNodes); }
    val bvhItems() const { return typedArray("Int32Array", stage_->bvhItems); }
    val lightCells() const { return typedArray("Int32Array", stage_->lightCells); }
    val lightItems() const { return typedArray("Int32Array", stage_->lightItems); }
    val eyeCells() const { return typedArray("Int32Array", stage_->eyeCells); }

    // The eye (scene file units) in the shaders' frame; rebuilds the eye
    // cells when it moved (then bvhItems() and eyeCells() change).
    val placeEye(float x, float y, float z) {
        const glm::vec3 eye = stage_->frame().point(glm::vec3(x, y, z));
        const bool moved = stage_->moveEye(eye);
        val out = val::object();
        out.set("eye", typedArray("Float32Array", std::vector<float>{eye.x, eye.y, eye.z}));
        out.set("eyeCellsMoved", moved);
        return out;
    }

private:
    std::unique_ptr<WebRayStage> stage_;
    std::string error_;
};

}  // namespace

}  // namespace raylab

EMSCRIPTEN_BINDINGS(raylab_core) {
    using raylab::RayStage;
    emscripten::class_<RayStage>("RayStage")
        .constructor<std::string>()
        .function("error", &RayStage::error)
        .function("info", &RayStage::info)
        .function("mapLog", &RayStage::mapLog)
        .function("sphereCentres", &RayStage::sphereCentres)
        .function("torusToLocal", &RayStage::torusToLocal)
        .function("bvhNodes", &RayStage::bvhNodes)
        .function("bvhItems", &RayStage::bvhItems)
        .function("lightCells", &RayStage::lightCells)
        .function("lightItems", &RayStage::lightItems)
        .function("eyeCells", &RayStage::eyeCells)
        .function("placeEye", &RayStage::placeEye);
}
