#pragma once
// Which files under assets/ a release to students holds: the scenes its
// stages draw (each stage's own and its check views') and the pictures and
// meshes those scenes name, nothing of a stage it does not hand out (a
// 01-03 release has no pro scene, no earth texture, no fur). Shared by
// `raylab web-bundle` and `raylab student-repo`. Students need not read
// this file.
#include "handout.h"

#include <filesystem>
#include <set>
#include <string>

namespace raylab {

// FILE (a scene of TRACK: "raytrace" or a fur scene) and the pictures and
// meshes it names, relative to the project's root. Throws Error for a
// scene that does not load, or that names a file outside the project.
std::set<std::string> sceneAssets(const std::string& track, const std::filesystem::path& file);

// The asset files STAGES (stage ids) use, relative to the project's root
// (assets/scenes/stage01.json, assets/textures/earth.png, ...), sorted.
// Throws Error for a scene that does not load (its file and cause).
std::set<std::string> releasedAssets(const std::set<std::string>& stages);

// The files PLAN's released stages use copied from the project into TO (a
// release's root), and assets/LICENSES.md cut down to them (its sections
// and table rows of files the release lacks left out, and the maintainers'
// <!-- with-solution --> paragraphs); with SCENES_README
// also assets/scenes/README.md, its tables of scene files cut down to the
// rows whose files are in the release.
void copyReleasedAssets(const std::filesystem::path& to, const std::vector<HandoutStage>& plan,
                        bool scenesReadme);

}  // namespace raylab
