#include "stage_sources.h"

#include "error.h"
#include "lab_files.h"
#include "lab_folder.h"
#include "paths.h"
#include "shader_source.h"

#include <map>

namespace raylab {

namespace fs = std::filesystem;

StageSources solutionSources(const StageInfo& stage) {
    StageSources s;
    s.label = "solution";
    const fs::path root = projectRoot();
    // The stage's own folder first, then the stages it builds on: a later
    // stage's file replaces an earlier one of the same name.
    for (const StageInfo* at = &stage; at;
         at = at->buildsOn.empty() ? nullptr : &findStage(at->buildsOn)) {
        s.search.push_back(root / "solution" / at->id);
        s.chain.push_back(at->id);
    }
    s.search.push_back(root / "framework" / "shaders");
    return s;
}

namespace {

// A project without its solutions' code (the web page served labs only:
// solution/<stage>/ holds its stage.json alone). The files a stage needs are
// then not known beforehand; assembling the lab names any that is missing.
bool solutionCodePresent(const StageInfo& stage) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(stage.folder(), ec))
        if (e.path().filename() != "stage.json") return true;
    return false;
}

}  // namespace

EarlierStages parseEarlierStages(const std::string& value, const std::string& where) {
    if (value == "own") return EarlierStages::Own;
    if (value == "solved") return EarlierStages::Solved;
    throw Error(where +
                ": expected \"solved\" (each stage graded with the earlier stages "
                "solved) or \"own\" (with the student's own earlier stages), not '" +
                value + "'");
}

StageSources labSources(const StageInfo& stage, const fs::path& labRoot, MissingLabFiles missing,
                        EarlierStages earlier) {
    std::error_code ec;
    if (!fs::is_directory(labRoot, ec))
        throw Error("lab folder " + labRoot.string() + " does not exist");
    if (!fs::is_directory(labRoot / stage.id, ec))
        throw Error("lab folder " + labRoot.string() + " has no " + stage.id +
                    "/ (it should be laid out like labs/)");
    StageSources s;
    std::string shown = displayPath(labRoot);
    while (shown.size() > 1 && shown.back() == '/') shown.pop_back();
    s.label = "lab " + shown + "/";
    s.chain = solutionSources(stage).chain;
    s.lab = true;
    s.labRoot = labRoot;
    s.earlierSolved = earlier == EarlierStages::Solved && s.chain.size() > 1;
    // The stage's folder, then the lab's folders of the stages it builds on
    // (Own), or the solutions of those stages (Solved). A file of the
    // stage's own that its folder lacks is taken from the lab as handed out
    // (FromHandedOutLab), in front of the solutions: a later stage may
    // replace an earlier stage's file of the same name.
    std::vector<fs::path> earlierDirs;
    s.search.push_back(labRoot / stage.id);
    for (std::size_t i = 1; i < s.chain.size(); ++i) {
        if (!s.earlierSolved && fs::is_directory(labRoot / s.chain[i], ec))
            s.search.push_back(labRoot / s.chain[i]);
        if (s.earlierSolved) earlierDirs.push_back(projectRoot() / "solution" / s.chain[i]);
    }
    if (s.earlierSolved) s.label += " (earlier stages solved)";
    std::vector<std::string> absent;
    const auto needed =
        solutionCodePresent(stage) ? labFileSources(stage) : std::map<std::string, LabFile>{};
    for (const auto& [name, file] : needed) {
        bool found = false;
        for (const fs::path& dir : s.search) found = found || fs::is_regular_file(dir / name, ec);
        for (const fs::path& dir : earlierDirs)
            found = found || fs::is_regular_file(dir / name, ec);
        if (!found) absent.push_back(name);
    }
    if (!absent.empty() && missing == MissingLabFiles::FromHandedOutLab) {
        s.filledIn = absent;
        s.search.push_back(handedOutLabRoot() / stage.id);
    } else if (!absent.empty()) {
        std::string names, folders;
        for (const std::string& n : absent) names += (names.empty() ? "" : ", ") + n;
        for (std::size_t i = 1; i < s.chain.size(); ++i)
            if (!fs::is_directory(labRoot / s.chain[i], ec))
                folders += (folders.empty() ? "" : ", ") + s.chain[i] + "/";
        throw Error(displayPath(labRoot / stage.id) + ": " + names +
                    (absent.size() == 1 ? " is" : " are") + " in none of its folders" +
                    (folders.empty() ? " (was a file deleted?)"
                                     : ": " + stage.id + " builds on your own " + folders +
                                           ", which " + displayPath(labRoot) +
                                           " lacks (copy them in beside " + stage.id + "/)"));
    }
    s.search.insert(s.search.end(), earlierDirs.begin(), earlierDirs.end());
    s.search.push_back(projectRoot() / "framework" / "shaders");
    return s;
}

std::vector<OwnEarlierStage> ownEarlierStagesRead(const StageInfo& stage,
                                                  const StageSources& sources) {
    std::vector<OwnEarlierStage> out;
    if (!sources.lab || sources.earlierSolved || sources.chain.size() < 2) return out;
    std::error_code ec;
    // Each file is read from the first folder of the search that has it.
    std::map<std::string, fs::path> readFrom;
    if (solutionCodePresent(stage)) {
        // The files the solution's programs read (a lab's own may not assemble).
        for (const auto& [name, file] : labFileSources(stage))
            for (const fs::path& dir : sources.search)
                if (fs::is_regular_file(dir / name, ec)) {
                    readFrom[name] = dir;
                    break;
                }
    } else {
        // A student repository holds no solution: the lab's own programs
        // say what they read (none when they do not assemble).
        try {
            for (const auto& [key, program] : stage.allPrograms())
                for (const std::string& entry :
                     {program->vertex, program->geometry, program->fragment}) {
                    if (entry.empty()) continue;
                    for (const fs::path& f :
                         assembleShader(entry, sources.search, stage.defines()).files)
                        readFrom.emplace(f.filename().string(), f.parent_path());
                }
        } catch (const Error&) { return out; }
    }
    // Newest first, as the search reads them.
    for (std::size_t i = 1; i < sources.chain.size(); ++i) {
        OwnEarlierStage e{sources.chain[i], {}};
        for (const auto& [name, dir] : readFrom)
            if (dir == sources.labRoot / e.id) e.files.push_back(name);
        if (!e.files.empty()) out.push_back(std::move(e));
    }
    return out;
}

namespace {

// Which define switches which variant folder on.
struct VariantSwitch {
    const char* define;
    bool whenDefined;  // false: the variant is used while the define is absent
    const char* folder;
};
constexpr VariantSwitch kVariants[] = {
    {"RAYLAB_NAIVE_NUMERICS", true, "naive-numerics"},        // textbook methods (tests/numerics)
    {"TORUS_SOLVER_CLOSED_FORM", true, "torus-closed-form"},  // the seed's torus solver
    {"RAYLAB_BVH", false, "linear-search"},                   // objects found by a plain loop
    {"RAYLAB_WEIGHT_CUT", true, "weight-cut"},  // rays too faint to count not traced (bench)
    {"RAYLAB_OLD_PATH", true, "old-path"},  // before the bench's levers: the glow ray and shadow
                                            // rays of lights behind a surface always cast
    {"RAYLAB_MESHES", true, "meshes"},      // stage 08 scenes with OBJ meshes
    {"RAYLAB_SHARED_WORK", true, "shared-work"},    // the same picture, less work (demo, bench)
    {"RAYLAB_LIGHT_BUFFER", true, "light-buffer"},  // shadow rays through a light buffer (demo)
    {"RAYLAB_EYE_CELLS", true, "eye-cells"},        // primary rays through the eye's cells (demo)
    {"RAYLAB_TREE_ALL", true,
     "tree-all"},  // the scene's triangles and discs in the BVH too (bench)
};

bool defined(const std::vector<std::string>& defines, const std::string& name) {
    for (const std::string& d : defines)
        if (d == name || d.rfind(name + " ", 0) == 0) return true;
    return false;
}

}  // namespace

std::vector<fs::path> searchWithVariants(const StageSources& sources,
                                         const std::vector<std::string>& defines) {
    const fs::path variants = projectRoot() / "framework" / "shaders" / "variants";
    std::vector<std::string> on;
    for (const VariantSwitch& v : kVariants)
        if (defined(defines, v.define) == v.whenDefined) on.push_back(v.folder);
    auto variantDirsFor = [&](const std::string& stageId, std::vector<fs::path>& out) {
        std::error_code ec;
        for (const std::string& folder : on)
            if (fs::is_directory(variants / folder / stageId, ec))
                out.push_back(variants / folder / stageId);
    };
    std::vector<fs::path> search;
    // A lab's folders hold the files of its whole chain: every variant of the
    // chain goes in front of the first.
    for (std::size_t i = 0; i < sources.search.size(); ++i) {
        if (sources.lab && i == 0) {
            for (const std::string& id : sources.chain) variantDirsFor(id, search);
        } else if (!sources.lab && i < sources.chain.size()) {
            variantDirsFor(sources.chain[i], search);
        }
        search.push_back(sources.search[i]);
    }
    return search;
}

fs::path defaultLabRoot() { return projectRoot() / "labs"; }

}  // namespace raylab
