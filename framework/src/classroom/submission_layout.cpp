#include "submission_layout.h"

#include "error.h"
#include "lab_folder.h"
#include "stage_catalog.h"
#include "stage_sources.h"
#include "zip_unpack.h"

#include <algorithm>
#include <set>

namespace raylab {

namespace fs = std::filesystem;

namespace {

bool isShaderFile(const fs::path& p) {
    const std::string ext = p.extension().string();
    return ext == ".glsl" || ext == ".vert" || ext == ".frag" || ext == ".geom";
}

bool isStageId(const std::string& name) {
    for (const StageInfo& s : allStages())
        if (s.id == name) return true;
    return false;
}

// The entries of DIR, hidden files and OS litter (__MACOSX) left out.
std::vector<fs::directory_entry> entries(const fs::path& dir) {
    std::vector<fs::directory_entry> out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.' || name == "__MACOSX") continue;
        out.push_back(*it);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// A stage folder as uploaded, its links left out (one into solution/ would
// hand in the solution) and said so.
void copyStageFolder(const fs::path& from, const fs::path& to, std::vector<std::string>& notes) {
    fs::create_directories(to);
    std::error_code ec;
    for (fs::recursive_directory_iterator it(from, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path rel = it->path().lexically_relative(from);
        if (it->is_symlink(ec)) {
            notes.push_back(from.filename().string() + "/" + rel.generic_string() +
                            ": a symbolic link, left out");
            if (it->is_directory(ec)) it.disable_recursion_pending();
        } else if (it->is_directory(ec)) {
            fs::create_directories(to / rel);
        } else if (it->is_regular_file(ec)) {
            fs::copy_file(it->path(), to / rel);
        }
    }
}

}  // namespace

SubmissionLayout layOutSubmission(const fs::path& uploaded, const std::vector<std::string>& stages,
                                  const fs::path& labRoot, const fs::path& scratch) {
    SubmissionLayout r;
    fs::path dir = uploaded;
    std::vector<fs::directory_entry> list = entries(dir);
    // A zip is the submission: unpacked, it is read like an upload of its files.
    std::vector<fs::directory_entry> zips;
    for (const auto& e : list)
        if (e.is_regular_file() && !e.is_symlink() && isZipFile(e.path())) zips.push_back(e);
    if (zips.size() > 1) {
        r.problem = "more than one zip file was submitted: upload one zip (of your labs folder, "
                    "or of some stage folders)";
        return r;
    }
    if (zips.size() == 1) {
        for (const auto& e : list)
            if (e.path() != zips[0].path())
                r.notes.push_back(e.path().filename().string() +
                                  ": beside a zip, only the zip is graded; left out");
        try {
            unpackZip(zips[0].path(), scratch);
        } catch (const Error& e) {
            r.problem = e.what();
            return r;
        }
        r.notes.push_back(zips[0].path().filename().string() + ": unpacked");
        dir = scratch;
        list = entries(dir);
    }
    // One folder that is not a stage: a zip's top folder around the real content.
    while (list.size() == 1 && list[0].is_directory() && !list[0].is_symlink() &&
           !isStageId(list[0].path().filename().string())) {
        dir = list[0].path();
        list = entries(dir);
    }
    if (list.empty()) {
        r.empty = zips.empty();
        r.problem = zips.empty() ? "nothing was submitted" : "the zip file is empty";
        return r;
    }
    fs::create_directories(labRoot);
    bool stageFolders = false;
    for (const auto& e : list)
        if (e.is_directory() && !e.is_symlink() && isStageId(e.path().filename().string()))
            stageFolders = true;
    if (stageFolders) {
        for (const auto& e : list) {
            const std::string name = e.path().filename().string();
            if (e.is_symlink()) r.notes.push_back(name + ": a symbolic link, left out");
            else if (e.is_directory() && isStageId(name))
                copyStageFolder(e.path(), labRoot / name, r.notes);
            else r.notes.push_back(name + ": not a stage folder, left out");
        }
        return r;
    }
    // Loose files: one stage's, over that lab's own files.
    if (stages.size() != 1) {
        r.problem =
            "loose files, but this assignment grades " + std::to_string(stages.size()) +
            " stages: upload stage folders (e.g. 01-raycast/) or a zip of your labs/ folder";
        return r;
    }
    const StageInfo& stage = findStage(stages[0]);
    fs::copy(handedOutLabRoot() / stage.id, labRoot / stage.id, fs::copy_options::recursive);
    int used = 0;
    for (const auto& e : list) {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && !e.is_symlink() && isShaderFile(e.path())) {
            fs::copy_file(e.path(), labRoot / stage.id / name,
                          fs::copy_options::overwrite_existing);
            ++used;
        } else {
            r.notes.push_back(name + ": not a shader file (.glsl, .vert, .frag, .geom), left out");
        }
    }
    if (used == 0)
        r.problem = "no shader files (.glsl, .vert, .frag, .geom) among the files submitted";
    return r;
}

}  // namespace raylab
