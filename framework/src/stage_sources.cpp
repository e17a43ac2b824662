#include "stage_sources.h"

#include "error.h"
#include "paths.h"

namespace raylab {

namespace fs = std::filesystem;

StageSources solutionSources(const StageInfo& stage) {
    StageSources s;
    s.label = "solution";
    const fs::path root = projectRoot();
    bool reached = false;
    const auto& stages = allStages();
    for (auto it = stages.rbegin(); it != stages.rend(); ++it) {
        if (it->id == stage.id) reached = true;
        std::error_code ec;
        if (reached && fs::is_directory(root / "solution" / it->id, ec)) s.search.push_back(root / "solution" / it->id);
    }
    s.search.push_back(root / "framework" / "shaders");
    return s;
}

StageSources labSources(const StageInfo& stage, const fs::path& labRoot) {
    std::error_code ec;
    if (!fs::is_directory(labRoot, ec)) throw Error("lab folder " + labRoot.string() + " does not exist");
    if (!fs::is_directory(labRoot / stage.id, ec))
        throw Error("lab folder " + labRoot.string() + " has no " + stage.id + "/ (it should be laid out like labs/)");
    StageSources s;
    s.label = "lab " + displayPath(labRoot) + "/";
    s.search = {labRoot / stage.id, projectRoot() / "framework" / "shaders"};
    return s;
}

fs::path defaultLabRoot() { return projectRoot() / "labs"; }

} // namespace raylab
