#pragma once
// The stages of the course, read from solution/<id>/stage.json (see
// solution/README.md for the format). Nothing in C++ knows a stage by its id
// or number: what a stage has (scene, limits, features, check views, function
// checks) is data, and the order of a track follows `builds_on`.
#include "camera.h"
#include "stage_grading.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace raylab {

// One camera view used to check a stage (tests, `raylab check`, grading).
struct CheckView {
    std::string name;
    std::string base;  // a seeded view (grading): the check view it varies; else empty
    std::optional<CameraPose> pose;  // none: the scene's own camera
    float time = 0.0f;
    std::string why;  // what this view exercises
    // A cause this view's picture alone shows, said when it fails and no
    // function check does (stage.json "hint"; the catalogue's "view:NAME").
    std::string hint;
    bool shadows = true;
    int maxDepth = 8;
    bool glow = true;
    bool normalMaps = true;
    int colorMode = 0;
    std::string scene;  // empty: the stage's scene; else a file under assets/scenes/
    // The fur track's switches (render_settings.h).
    int shells = 0;  // 0: the scene's shell count
    bool fins = true;
    int furTechnique = 0;  // index into kFurTechniques
};

// The shader files a stage's program is built from (names on its search path).
struct StageProgram {
    std::string vertex;
    std::string geometry;  // empty: no geometry shader
    std::string fragment;
};

// The most of each kind of object a stage's shader is compiled for.
struct StageLimits {
    int spheres = 16;
    int materials = 16;
    int lights = 4;
    int planes = 0;  // 0: this stage has no such objects
    int discs = 0;
    int triangles = 0;
    int tori = 0;
    // Triangles of OBJ meshes: in textures (memory), so no uniform limit; 0:
    // this stage draws no meshes, else the most the hit ids can number.
    int meshTriangles = 0;
    int textures = 0;  // texture layers (pictures and normal maps)
    bool skyBox = false;
};

struct StageInfo {
    std::string id;        // "01-raycast", the folder name
    std::string title;     // one line for `raylab stages`
    std::string track;     // "raytrace"
    std::string buildsOn;  // the stage whose files this one inherits; empty for none
    std::string scene;     // default scene, relative to assets/scenes/
    // "technique": the fur technique its pictures show by default (index into
    // kFurTechniques): the stage's own work (f4: the fur shader; T switches).
    int furTechnique = 0;
    StageProgram program;
    // More programs a track's renderer draws with, by name (the fur track's
    // "fins" and "strands"); their files are the stage's like the main one's.
    std::map<std::string, StageProgram> programs;
    StageLimits limits;
    std::set<std::string> features;           // see kKnownFeatures in stage_catalog.cpp
    std::vector<std::string> functionChecks;  // names of function checks (function_checks.h)
    std::vector<std::string> countChecks;     // names of count checks (track_renderer.h)
    std::filesystem::path mistakes;  // the mistakes catalogue, relative to the project root
    std::vector<CheckView> checkViews;
    std::vector<std::string> extraDefines;  // besides the limits ("defines" in stage.json)
    // The usual causes of a failed view that is mostly too dark or too
    // bright, for hints ("hints": {"darker": ..., "brighter": ...}); empty:
    // hints state the fact alone.
    std::string hintDarker, hintBrighter;
    // How its 100 points are shared and the credit curves' use
    // ("grading" in stage.json; stage_grading.h).
    StageGrading grading;
    // The name a view's points are weighed by: a seeded view's base.
    static const std::string& weightName(const CheckView& view) {
        return view.base.empty() ? view.name : view.base;
    }

    bool has(const std::string& feature) const { return features.count(feature) > 0; }
    // The part of the id before the first '-' ("01" of "01-raycast"): what
    // `--stage 01` and messages such as "stage 06 adds it" use.
    std::string number() const { return id.substr(0, id.find('-')); }
    // MAX_SPHERES, MAX_MATERIALS, MAX_LIGHTS, MAX_PLANES, ... (at least 1:
    // GLSL has no empty arrays) and the extra defines.
    std::vector<std::string> defines() const;
    std::filesystem::path folder() const;  // solution/<id>
    // The scene file VIEW draws: its own "scene", else the stage's, under
    // assets/scenes/.
    std::filesystem::path sceneFileOf(const CheckView& view) const;
    // The main program and the named ones, with their stage.json keys.
    std::vector<std::pair<std::string, const StageProgram*>> allPrograms() const;
};

// Reads one stage.json. Throws Error("FILE: KEY: what is wrong").
StageInfo readStageFile(const std::filesystem::path& file);

struct JsonReader;
// A "grading" object (stage_grading.h) over GRADING: what it sets replaces,
// the rest stays. WHERE names it in errors. Not validated against a stage
// (validateGrading does).
StageGrading readGrading(const JsonReader& reader, const nlohmann::json& value,
                         const std::string& where, StageGrading grading);

// Every stage, track by track, each track in `builds_on` order.
const std::vector<StageInfo>& allStages();

// Accepts "01-raycast", "01", "1", or "f2" for "f2-shells". Throws Error listing the stage ids.
const StageInfo& findStage(const std::string& idOrNumber);

// STAGE's program NAME ("fins", "strands"), which FEATURE needs; throws
// Error naming stage.json when the stage has none.
const StageProgram& namedProgram(const StageInfo& stage, const char* name, const char* feature);

// The stage `raylab demo` and `raylab bench` run for TRACK: its last stage
// with the "demo" feature.
const StageInfo& demoStage(const std::string& track = "raytrace");

}  // namespace raylab
