#include "release_assets.h"

#include "atomic_file.h"
#include "error.h"
#include "fur_scene.h"
#include "lab_folder.h"
#include "paths.h"
#include "scene.h"
#include "stage_catalog.h"
#include "student_release.h"

#include <sstream>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// FILE (as SCENE's reader resolved it) relative to the project's root. A
// file outside the project is refused: a release copies the project's
// files, and the path would lead out of the release's folder.
std::string projectRelative(const fs::path& file, const fs::path& scene) {
    const fs::path rel =
        fs::weakly_canonical(file).lexically_relative(fs::weakly_canonical(projectRoot()));
    if (rel.empty() || rel.is_absolute() || *rel.begin() == "..")
        throw Error(displayPath(scene) + ": " + file.string() +
                    " is outside the project, and a release to students holds the project's "
                    "files only (put it under assets/)");
    return rel.generic_string();
}

// The row of a table of FOLDER's files (assets/scenes/README.md's scenes,
// assets/LICENSES.md's textures) kept when every file it names (`name` in
// its first cell) is in the release.
bool rowShipped(const std::string& line, const std::set<std::string>& files,
                const std::string& folder) {
    if (line.rfind("| `", 0) != 0) return true;  // not a row of the table
    const std::string cell = line.substr(0, line.find('|', 1));
    for (std::size_t at = cell.find('`'); at != std::string::npos;) {
        const std::size_t end = cell.find('`', at + 1);
        if (end == std::string::npos) break;
        if (!files.count(folder + cell.substr(at + 1, end - at - 1))) return false;
        at = cell.find('`', end + 1);
    }
    return true;
}

// assets/LICENSES.md as a release holds it: the sections on a folder
// ("## Textures (`assets/textures/`)") only where the release holds files
// of that folder, their tables cut down to its files, and without the
// maintainers' paragraphs (<!-- with-solution -->: how to regenerate the
// files, with tools a release does not hold).
std::string releasedLicences(const std::set<std::string>& files) {
    const std::string file = "assets/LICENSES.md";
    std::istringstream in(guideAtLevel(readTextFile(projectRoot() / file), Level::Guided, file,
                                       SolutionText::LeaveOut));
    std::string out, line, folder;  // folder: the section's, "assets/textures/"
    bool kept = true;
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) {
            const std::size_t at = line.find("(`"), end = line.find("`)");
            folder = at != std::string::npos && end > at ? line.substr(at + 2, end - at - 2) : "";
            const auto first = files.lower_bound(folder);
            kept = folder.empty() ||
                   (first != files.end() && first->compare(0, folder.size(), folder) == 0);
        }
        if (kept && rowShipped(line, files, folder)) out += line + "\n";
    }
    return out;
}

}  // namespace

std::set<std::string> sceneAssets(const std::string& track, const fs::path& file) {
    std::set<std::string> out;
    auto add = [&](const fs::path& named) { out.insert(projectRelative(named, file)); };
    add(file);
    if (track == "raytrace") {
        const Scene s = loadScene(file);
        for (const fs::path& t : s.textures) add(t);
        if (s.skyBox)
            for (const fs::path& face : *s.skyBox) add(face);
        for (const MeshObject& m : s.meshes) add(m.file);
    } else {
        const FurScene s = loadFurScene(file);
        for (const fs::path& p : {s.fur.colorMap, s.fur.pattern, s.fur.finMap})
            if (!p.empty()) add(p);
        if (!s.mesh.obj.empty()) add(s.mesh.obj);
    }
    return out;
}

std::set<std::string> releasedAssets(const std::set<std::string>& stages) {
    std::set<std::string> files;
    for (const StageInfo& s : allStages()) {
        if (!stages.count(s.id)) continue;
        // Each scene once (most views share the stage's own).
        std::set<fs::path> scenes = {s.sceneFileOf(CheckView{})};
        for (const CheckView& view : s.checkViews) scenes.insert(s.sceneFileOf(view));
        for (const fs::path& scene : scenes) files.merge(sceneAssets(s.track, scene));
    }
    return files;
}

void copyReleasedAssets(const fs::path& to, const std::vector<HandoutStage>& plan,
                        bool scenesReadme) {
    const fs::path root = projectRoot();
    std::set<std::string> stages;
    for (const HandoutStage& h : plan) stages.insert(h.stage->id);
    const std::set<std::string> files = releasedAssets(stages);
    for (const std::string& f : files) copyTree(root / f, to / f);
    writeTextFileAtomic(to / "assets" / "LICENSES.md", releasedLicences(files));
    if (!scenesReadme) return;
    std::istringstream in(readTextFile(root / "assets" / "scenes" / "README.md"));
    std::string text, line;
    while (std::getline(in, line))
        if (rowShipped(line, files, "assets/scenes/")) text += line + "\n";
    writeTextFileAtomic(to / "assets" / "scenes" / "README.md", text);
}

}  // namespace raylab
