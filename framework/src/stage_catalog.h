#pragma once
// The stages of the course, in the order the seed thesis builds the tracer.
// A stage exists once solution/<id>/ does; labs/<id>/ is generated from it.
#include "camera.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

// One camera view used to check a stage (tests, `raylab check`, grading).
struct CheckView {
    std::string name;
    std::optional<CameraPose> pose;  // none: the scene's own camera
    float time = 0.0f;
    std::string why;  // what this view exercises
    bool shadows = true;
    int maxDepth = 8;
    bool glow = true;
    bool normalMaps = true;
    int colorMode = 0;
    std::string scene;  // empty: the stage's scene; else a file under assets/scenes/
};

struct StageInfo {
    std::string id;                 // "01-raycast"
    std::string title;              // one line for `raylab stages`
    std::string scene;              // default scene, relative to assets/scenes/
    std::vector<std::string> extraDefines;  // besides the scene limits below
    int maxSpheres = 16;            // scene limits the shader is compiled for
    int maxMaterials = 16;
    int maxLights = 4;
    int maxPlanes = 0;              // 0: this stage has no such objects
    int maxDiscs = 0;
    int maxTriangles = 0;
    int maxTori = 0;
    int maxTextures = 0;            // texture layers (pictures and normal maps)
    bool skyBox = false;            // draws a sky box
    std::vector<CheckView> checkViews;

    std::string number() const { return id.substr(0, 2); }
    // MAX_SPHERES, MAX_MATERIALS, MAX_LIGHTS, MAX_PLANES, ... (at least 1:
    // GLSL has no empty arrays) and the extra defines.
    std::vector<std::string> defines() const;
    bool available() const;         // solution/<id>/ exists
};

const std::vector<StageInfo>& allStages();

// Accepts "01-raycast", "01" or "1". Throws Error listing the stage ids.
const StageInfo& findStage(const std::string& idOrNumber);

// The highest stage whose solution exists.
const StageInfo& latestAvailableStage();

} // namespace raylab
