// The page's entry into the core (embind): web/src/core/core.ts is its only
// caller (RayStage: a ray-tracing stage; FurStage: a fur stage; the checks are
// in check_bindings.cpp). Requests and small answers are
// JSON text; arrays of numbers are typed arrays (copies: wasm memory may move when it grows). A
// constructor never throws into JavaScript: errors, with native's text, are kept and read through
// error(). Students need not read this file.
#include "embind_support.h"
#include "error.h"
#include "gpu_values.h"
#include "mesh_shapes.h"
#include "web_fur_stage.h"
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

json vec3Json(glm::vec3 v) { return {v.x, v.y, v.z}; }
json vec3Json(const glm::dvec3& v) { return {v.x, v.y, v.z}; }  // a scene's positions

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
            q.todoMarks = r.value("todoMarks", false);
            q.view = r.value("view", "color");
            q.trace = r.value("trace", false);
            stage_ = std::make_unique<WebRayStage>(q);
        } catch (const std::exception& e) { error_ = e.what(); }
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

    val sphereCentres(float t) const {
        return typedArray("Float32Array", stage_->sphereCentres(t));
    }
    val torusToLocal(float t) const { return typedArray("Float32Array", stage_->torusToLocal(t)); }
    val bvhNodes() const { return typedArray("Float32Array", stage_->bvhNodes); }
    val bvhItems() const { return typedArray("Int32Array", stage_->bvhItems); }
    val lightCells() const { return typedArray("Int32Array", stage_->lightCells); }
    val lightItems() const { return typedArray("Int32Array", stage_->lightItems); }
    val eyeCells() const { return typedArray("Int32Array", stage_->eyeCells); }
    val meshCorners() const { return typedArray("Float32Array", stage_->meshCorners); }
    val meshMaterials() const { return typedArray("Int32Array", stage_->meshMaterials); }

    // The eye (scene file units, double: JavaScript's numbers) in the
    // shaders' frame, moved there in double and rounded once; rebuilds the
    // eye cells when it moved (then bvhItems() and eyeCells() change).
    val placeEye(double x, double y, double z) {
        const glm::vec3 eye = gpuPoint(stage_->frame().point(glm::dvec3(x, y, z)));
        const bool moved = stage_->moveEye(eye);
        val out = val::object();
        out.set("eye", typedArray("Float32Array", std::vector<float>{eye.x, eye.y, eye.z}));
        out.set("eyeCellsMoved", moved);
        return out;
    }

    // With the trace build: pixel (X, Y)'s path, from SUMMARY (4 floats)
    // and RECORDS (16 per call): {report} or {error}.
    val traceReport(const val& summary, const val& records, int x, int y, int width,
                    int height) const {
        val out = val::object();
        try {
            out.set("report",
                    stage_->traceReport(emscripten::convertJSArrayToNumberVector<float>(summary),
                                        emscripten::convertJSArrayToNumberVector<float>(records), x,
                                        y, width, height));
        } catch (const std::exception& e) { out.set("error", std::string(e.what())); }
        return out;
    }

    // The debug view's picture of FLOATS (RGBA, rows bottom-up, WIDTH x
    // HEIGHT): {rgba (top-down bytes), mapping} or {error}.
    val viewPicture(const val& floats, int width, int height) const {
        val out = val::object();
        try {
            std::string mapping;
            const Image image = stage_->viewPicture(
                emscripten::convertJSArrayToNumberVector<float>(floats), width, height, &mapping);
            out.set("rgba", typedArray("Uint8Array", image.rgba));
            out.set("mapping", mapping);
        } catch (const std::exception& e) { out.set("error", std::string(e.what())); }
        return out;
    }

private:
    std::unique_ptr<WebRayStage> stage_;
    std::string error_;
};

// A driver's log with the assembled lines mapped to file:line (native's
// mapCompilerLog) for SOURCEJSON, a source as info() gives it.
std::string mapLog(const std::string& log, const std::string& sourceJson) {
    try {
        const json j = json::parse(sourceJson);
        ShaderSource s;
        s.text = j.at("text").get<std::string>();
        for (const json& o : j.at("origin")) s.origin.push_back({o.at(0), o.at(1)});
        return mapCompilerLog(log, s);
    } catch (const std::exception&) {
        return log;  // an unmapped log beats none
    }
}

json programsJson(const WebFurPrograms& p) {
    json out = {{"vertex", sourceJson(p.vertex)}, {"fragment", sourceJson(p.fragment)}};
    if (p.geometry) {
        out["geometry"] = sourceJson(p.geometry->expand);
        out["geometryDraw"] = sourceJson(p.geometry->draw);
        out["captureFragment"] = sourceJson(p.captureFragment);
        out["emulation"] = json::parse(p.geometry->json());
    }
    return out;
}

// A fur stage for the page (web_fur_stage.h).
class FurStage {
public:
    explicit FurStage(const std::string& requestJson) {
        try {
            const json r = json::parse(requestJson);
            stage_ =
                std::make_unique<WebFurStage>(r.value("stage", ""), r.value("lab", ""),
                                              r.value("scene", ""), r.value("todoMarks", false));
        } catch (const std::exception& e) { error_ = e.what(); }
    }
    std::string error() const { return error_; }

    std::string info() const {
        if (!stage_) return "{}";
        const WebFurStage& s = *stage_;
        const FurScene& scene = s.scene();
        const FurParameters& f = scene.fur;
        json todos = json::array();
        for (const OpenTodo& t : s.todos())
            todos.push_back({{"file", t.file}, {"line", t.line}, {"title", t.title}});
        json programs = {{"shells", programsJson(s.shells())}};
        if (s.fins()) programs["fins"] = programsJson(*s.fins());
        if (s.strands()) programs["strands"] = programsJson(*s.strands());
        json strands = nullptr;
        if (s.strandBudget())
            strands = {{"perTriangle", s.strandBudget()->strandsPerTriangle},
                       {"vertices", s.strandBudget()->segments + 1}};
        const CameraPose& cam = scene.camera;
        return json{
            {"stage", s.stage().id},
            {"sceneFile", scene.file},
            {"programs", programs},
            {"todos", todos},
            {"background", vec3Json(scene.background)},
            {"camera",
             {{"position", vec3Json(cam.position)},
              {"yaw", cam.yawDeg},
              {"pitch", cam.pitchDeg},
              {"fovY", scene.fovYDeg}}},
            {"lightDirection", vec3Json(scene.lightDirection)},
            {"lightColor", vec3Json(scene.lightColor)},
            {"ambient", vec3Json(scene.ambient)},
            {"fur",
             {{"length", f.length},
              {"shells", f.shells},
              {"patternScale", f.patternScale},
              {"shadowIntensity", f.shadowIntensity},
              {"gravity", f.gravity},
              {"strandDensity", f.strandDensity},
              {"strandSegments", f.strandSegments}}},
            {"textures", {f.colorMap.string(), f.pattern.string(), f.finMap.string()}},
            {"bounds", {{"centre", vec3Json(s.boundsCentre())}, {"radius", s.boundsRadius()}}},
            {"strands", strands},
            {"shapes", shapeNames()},
            {"mesh",
             {{"name", s.mesh().name},
              {"vertices", s.mesh().vertexCount()},
              {"triangles", s.mesh().triangleCount()}}}}
            .dump();
    }

    val positions() const { return vec3Array(stage_->mesh().positions); }
    val normals() const { return vec3Array(stage_->mesh().normals); }
    val uvs() const {
        std::vector<float> out;
        for (glm::vec2 v : stage_->mesh().uvs) out.insert(out.end(), {v.x, v.y});
        return typedArray("Float32Array", out);
    }
    val indices() const { return typedArray("Uint32Array", stage_->mesh().indices); }
    val adjacency() const { return typedArray("Uint32Array", stage_->adjacency().indices); }
    // The procedural mesh FURMESH (1.. of shapes) instead of the scene's (0),
    // the native window's key M; the mesh's arrays and info() change.
    void showMesh(int furMesh) { stage_->showMesh(furMesh); }
    // The fin count check's verdict on EMITTED fins in the stage's check
    // view VIEW: {passed, detail}, or {error} (tables without the view).
    std::string finCount(double emitted, const std::string& view) const {
        try {
            const FinCountVerdict v = stage_->finCount(long(emitted), view);
            return json{{"passed", v.passed}, {"detail", v.detail}}.dump();
        } catch (const Error& e) { return json{{"error", e.what()}}.dump(); }
    }
    // The model matrix at time T, column-major.
    val modelMatrix(float t) const {
        const glm::mat4 m = stage_->scene().modelMatrix(t);
        std::vector<float> out;
        for (int c = 0; c < 4; ++c) out.insert(out.end(), {m[c].x, m[c].y, m[c].z, m[c].w});
        return typedArray("Float32Array", out);
    }

private:
    static val vec3Array(const std::vector<glm::vec3>& v) {
        std::vector<float> out;
        out.reserve(3 * v.size());
        for (glm::vec3 p : v) out.insert(out.end(), {p.x, p.y, p.z});
        return typedArray("Float32Array", out);
    }
    std::unique_ptr<WebFurStage> stage_;
    std::string error_;
};

}  // namespace

}  // namespace raylab

EMSCRIPTEN_BINDINGS(raylab_core) {
    emscripten::function("mapCompilerLog", &raylab::mapLog);
    using raylab::RayStage;
    emscripten::class_<RayStage>("RayStage")
        .constructor<std::string>()
        .function("error", &RayStage::error)
        .function("info", &RayStage::info)
        .function("sphereCentres", &RayStage::sphereCentres)
        .function("torusToLocal", &RayStage::torusToLocal)
        .function("bvhNodes", &RayStage::bvhNodes)
        .function("bvhItems", &RayStage::bvhItems)
        .function("lightCells", &RayStage::lightCells)
        .function("lightItems", &RayStage::lightItems)
        .function("eyeCells", &RayStage::eyeCells)
        .function("meshCorners", &RayStage::meshCorners)
        .function("meshMaterials", &RayStage::meshMaterials)
        .function("placeEye", &RayStage::placeEye)
        .function("viewPicture", &RayStage::viewPicture)
        .function("traceReport", &RayStage::traceReport);
    using raylab::FurStage;
    emscripten::class_<FurStage>("FurStage")
        .constructor<std::string>()
        .function("error", &FurStage::error)
        .function("info", &FurStage::info)
        .function("positions", &FurStage::positions)
        .function("normals", &FurStage::normals)
        .function("uvs", &FurStage::uvs)
        .function("indices", &FurStage::indices)
        .function("adjacency", &FurStage::adjacency)
        .function("modelMatrix", &FurStage::modelMatrix)
        .function("finCount", &FurStage::finCount)
        .function("showMesh", &FurStage::showMesh);
}
