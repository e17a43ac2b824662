#include "stage_setup.h"

#include "error.h"
#include "paths.h"

#include <cmath>
#include <cstdio>

namespace raylab {

StageSetup resolveStageOptions(const StageOptions& o) {
    StageSetup s;
    if (o.labGiven && o.solution) throw Error("--lab and --solution exclude each other");
    if (!std::isfinite(o.time) || std::fabs(o.time) > 1e6f)
        throw Error("--time must be a finite number of seconds");
    s.stage = &findStage(o.stage);
    s.sources = o.solution
                    ? solutionSources(*s.stage)
                    : labSources(*s.stage, o.labDir.empty() ? defaultLabRoot()
                                                            : std::filesystem::path(o.labDir));
    s.size = parseSize(o.size);
    std::filesystem::path sceneFile = o.scene.empty()
                                          ? projectRoot() / "assets" / "scenes" / s.stage->scene
                                          : std::filesystem::path(o.scene);
    s.scene = loadScene(sceneFile);
    s.camera = cameraFor(o.camera.empty() ? std::nullopt
                                          : std::optional<CameraPose>(parseCamera(o.camera)),
                         s.scene);
    s.time = o.time;
    s.settings.shadows = !o.noShadows;
    if (o.maxDepth < 1 || o.maxDepth > RenderSettings::kMaxDepth)
        throw Error("--depth must be between 1 and 8");
    s.settings.maxDepth = o.maxDepth;
    s.settings.glow = !o.noGlow;
    s.settings.normalMaps = !o.noNormalMaps;
    s.settings.colorMode = -1;
    for (int i = 0; i < kColorModeCount; ++i)
        if (o.colorMode == kColorModes[i]) s.settings.colorMode = i;
    if (s.settings.colorMode < 0)
        throw Error("--color-mode must be one of RGB, BRB, BRR, RBB, GGR (not '" + o.colorMode +
                    "')");
    return s;
}

std::string demoSceneFile(const std::string& name) {
    if (name == "lite" || name == "pro")
        return (projectRoot() / "assets" / "scenes" / (name + ".json")).string();
    return name;
}

Camera cameraFor(const std::optional<CameraPose>& pose, const Scene& scene) {
    return Camera(pose ? *pose : scene.camera, scene.fovYDeg);
}

void reportOpenTodos(const std::vector<OpenTodo>& todos) {
    static bool reported = false;
    if (todos.empty() || reported) return;
    reported = true;
    std::fprintf(stderr,
                 "raylab: %zu open TODO%s in this lab (in colour frames their pixels show magenta "
                 "stripes):\n",
                 todos.size(), todos.size() == 1 ? "" : "s");
    for (const OpenTodo& t : todos)
        std::fprintf(stderr, "  %s:%d: %s\n", t.file.c_str(), t.line, t.title.c_str());
}

}  // namespace raylab
