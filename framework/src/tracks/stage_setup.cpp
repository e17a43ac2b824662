#include "stage_setup.h"

#include "check_report.h"
#include "error.h"
#include "json_reader.h"
#include "paths.h"
#include "scene_transform.h"
#include "track_registry.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace raylab {

namespace {

// The index of VALUE in NAMES, or Error("FLAG must be one of ...").
template <std::size_t N>
int choice(const char* flag, const std::string& value, const char* const (&names)[N]) {
    std::string all;
    for (std::size_t i = 0; i < N; ++i) {
        if (value == names[i]) return int(i);
        all += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + names[i];
    }
    throw Error(std::string(flag) + " must be " + all + " (not '" + value + "')");
}

}  // namespace

StageSetup resolveStageOptions(const StageOptions& o) {
    StageSetup s;
#ifdef RAYLAB_STUDENT_BUILD
    if (o.solution)
        throw Error("--solution: this is a student repository, which holds no solution (raylab "
                    "check compares your lab with the course's pictures in course/references/)");
#endif
    if (o.labGiven && o.solution) throw Error("--lab and --solution exclude each other");
    if (!std::isfinite(o.time) || std::fabs(o.time) > 1e6f)
        throw Error("--time must be a finite number of seconds");
    s.stage = &findStage(o.stage);
    s.sources = o.solution
                    ? solutionSources(*s.stage)
                    : labSources(*s.stage, o.labDir.empty() ? defaultLabRoot()
                                                            : std::filesystem::path(o.labDir));
    s.size = parseSize(o.size);
    s.sceneFile = o.scene.empty() ? stageSceneFile(s.stage->scene)
                                  : std::filesystem::path(demoSceneFile(o.scene));
    SceneTransform& transform = s.transform;
    if (!o.sceneScale.empty()) transform.scale = parseSceneScale(o.sceneScale);
    if (!o.sceneOffset.empty()) transform.offset = parseSceneOffset(o.sceneOffset);
    if (!transform.identity() && s.stage->track != "raytrace")
        throw Error("--scene-scale and --scene-offset are for the ray-tracing stages");
    const std::optional<CameraPose> pose =
        o.camera.empty() ? std::nullopt : std::optional<CameraPose>(parseCamera(o.camera));
    if (s.stage->track == "raytrace") s.scene = loadScene(s.sceneFile);
    else checkTrackScene(*s.stage, s.sceneFile);
    if (transform.identity()) {
        s.camera = cameraFor(pose, s.sceneFile);
    } else {
        s.scene = transformScene(s.scene, transform);
        s.camera = cameraFor(pose ? std::optional<CameraPose>(transformPose(*pose, transform))
                                  : std::nullopt,
                             s.scene);
    }
    s.time = o.time;
    s.settings.shadows = !o.noShadows;
    if (o.maxDepth < 1 || o.maxDepth > RenderSettings::kMaxDepth)
        throw Error("--depth must be between 1 and 8");
    s.settings.maxDepth = o.maxDepth;
    s.settings.glow = !o.noGlow;
    s.settings.normalMaps = !o.noNormalMaps;
    s.settings.colorMode = choice("--color-mode", o.colorMode, kColorModes);
    if (o.shells < 0 || o.shells > RenderSettings::kMaxShells)
        throw Error("--shells must be between 1 and " + std::to_string(RenderSettings::kMaxShells));
    s.settings.shells = o.shells;
    if (!(o.furLength > 0.0f) || o.furLength > 10.0f)
        throw Error("--fur-length must be a factor above 0 and at most 10");
    s.settings.furLength = o.furLength;
    s.settings.fins = !o.noFins;
    // Without --technique: the stage's own (stage.json "technique").
    s.settings.furTechnique = o.technique.empty()
                                  ? s.stage->furTechnique
                                  : choice("--technique", o.technique, kFurTechniques);
    return s;
}

std::filesystem::path demoScenePath(const std::string& name) {
    return projectRoot() / "assets" / "scenes" / (name + ".json");
}

std::string demoSceneFile(const std::string& name) {
    if (name == "lite" || name == "pro") {
        const std::filesystem::path file = demoScenePath(name);
        std::error_code ec;
        // A student repository holds the scenes of its released stages only.
        if (!std::filesystem::is_regular_file(file, ec)) {
            std::set<std::string> scenes;
            for (const auto& e : std::filesystem::directory_iterator(file.parent_path(), ec))
                if (e.path().extension() == ".json") scenes.insert(e.path().filename().string());
            std::string held;
            for (const std::string& s : scenes) held += (held.empty() ? "" : ", ") + s;
            throw Error("--scene " + name + ": assets/scenes/" + name +
                        ".json is not in this repository (it holds the scenes of the stages "
                        "released so far" +
                        (held.empty() ? std::string(")") : ": " + held + ")"));
        }
        return file.string();
    }
    // A guide's "--scene assets/scenes/fur/coarse.json" run from a handout
    // folder: a relative path not found here is the project's.
    const std::filesystem::path path(name);
    std::error_code ec;
    if (!name.empty() && path.is_relative() && !std::filesystem::exists(path, ec) &&
        std::filesystem::is_regular_file(projectRoot() / path, ec))
        return (projectRoot() / path).string();
    return name;
}

Camera cameraFor(const std::optional<CameraPose>& pose, const Scene& scene) {
    return Camera(pose ? *pose : scene.camera, scene.fovYDeg);
}

Camera cameraFor(const std::optional<CameraPose>& pose, const std::filesystem::path& sceneFile) {
    const SceneCamera c = loadSceneCamera(sceneFile);
    return Camera(pose ? *pose : c.pose, c.fovYDeg);
}

std::filesystem::path stageSceneFile(const std::string& name) {
    return projectRoot() / "assets" / "scenes" / name;
}

void reportOpenTodos(const std::vector<OpenTodo>& todos) {
    static bool reported = false;
    if (todos.empty() || reported) return;
    reported = true;
    std::fputs(formatOpenTodos(todos).c_str(), stderr);
}

}  // namespace raylab
