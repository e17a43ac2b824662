#pragma once
// What every command that draws a stage needs: which stage, whose shaders
// (lab or solution), which scene, image size and camera - from the command
// line, checked, with one-line errors.
#include "camera.h"
#include "cli_parse.h"
#include "render_settings.h"
#include "scene.h"
#include "scene_transform.h"
#include "shader_source.h"
#include "stage_catalog.h"
#include "stage_sources.h"

#include <filesystem>
#include <optional>
#include <string>

namespace raylab {

struct StageOptions {
    std::string stage;
    bool labGiven = false;  // --lab with or without a folder
    std::string labDir;     // empty: labs/
    bool solution = false;
    std::string scene;  // empty: the stage's default scene
    std::string size = "800x600";
    std::string camera;  // empty: the scene's camera
    // The whole scene resized and moved (ray-tracing stages): "" is 1 and
    // 0,0,0. The depth view then measures in the new units; --camera is
    // given in the scene file's units and moved with the scene.
    std::string sceneScale, sceneOffset;
    float time = 0.0f;
    bool noShadows = false;
    int maxDepth = RenderSettings::kMaxDepth;
    bool noGlow = false;
    bool noNormalMaps = false;
    std::string colorMode = "RGB";
    // The fur track.
    int shells = 0;  // 0: the scene's
    float furLength = 1.0f;
    bool noFins = false;
    std::string technique;  // empty: the stage's own (stage.json "technique")
};

struct StageSetup {
    const StageInfo* stage = nullptr;
    StageSources sources;
    std::filesystem::path sceneFile;
    Scene scene;               // ray-tracing stages only (the fur renderer reads its own scenes)
    SceneTransform transform;  // --scene-scale, --scene-offset: already applied to scene
    Size size;
    Camera camera;
    float time = 0.0f;
    RenderSettings settings;
};

// Validates everything before any window or context is created.
StageSetup resolveStageOptions(const StageOptions& options);

// "lite" and "pro" name the demo scenes (assets/scenes/); anything else is a
// scene file as given, or, when a relative path is not found from the current
// folder, the project's (a guide's command run from a handout folder). Empty
// stays empty (the stage's own scene).
std::string demoSceneFile(const std::string& name);
// Where the demo scene NAME ("lite" or "pro") lives, whether or not this
// repository holds it (a student repository holds it once stage 08 is out).
std::filesystem::path demoScenePath(const std::string& name);

// The camera a check view uses in SCENE.
Camera cameraFor(const std::optional<CameraPose>& pose, const Scene& scene);
// The same for a scene file of any track; the file's camera is read once.
Camera cameraFor(const std::optional<CameraPose>& pose, const std::filesystem::path& sceneFile);

// assets/scenes/NAME: where stage.json's "scene" and a check view's "scene" point.
std::filesystem::path stageSceneFile(const std::string& name);

// Prints the open TODOs of a lab to stderr, once per program run.
void reportOpenTodos(const std::vector<OpenTodo>& todos);

}  // namespace raylab
