#include "handout_folder.h"

#include "atomic_file.h"
#include "error.h"
#include "lab_folder.h"
#include "paths.h"
#include "stage_grading.h"

#include <unistd.h>

#include <algorithm>

namespace raylab {

namespace fs = std::filesystem;

namespace {

std::string readme(const std::vector<HandoutStage>& plan) {
    std::string text = "# Your labs\n\nThe stages released so far, one folder each, with its guide "
                       "(README.md):\n\n";
    bool reads = false;
    for (const HandoutStage& h : plan) {
        text += "- [" + h.stage->id + "](" + h.stage->id + "/README.md): " + h.stage->title + "\n";
        reads = reads || !h.fromStudent.empty();
    }
    const std::string first = plan.front().stage->number();
    text += "\nWork in the TODO blocks of each stage's files. From the RayLab folder:\n\n"
            "    build/raylab run --stage " +
            first + " --lab THIS_FOLDER\n    build/raylab check --stage " + first +
            " --lab THIS_FOLDER\n\n";
    if (reads)
        text += "A stage folder holds only the files that stage adds. The files of the stages it "
                "builds on are read from your own folders of those stages, here beside it, so "
                "keep every stage folder you have been given in one folder: what you fix in an "
                "earlier stage shows in the later ones too. Each guide says which files come "
                "from where.\n\n";
    text += "Later stages arrive as new folders; copy them in beside these.\n";
    return text;
}

}  // namespace

void checkHandoutSources(const std::vector<HandoutStage>& plan, const fs::path& labs) {
    std::error_code ec;
    for (const HandoutStage& h : plan)
        for (const std::string& name : h.files())
            if (!fs::is_regular_file(labs / h.stage->id / name, ec))
                throw Error("lab file " + (labs / h.stage->id / name).string() +
                            " does not exist (regenerate labs/ with raylab-labgen)");
}

void writeHandoutFolder(const std::vector<HandoutStage>& plan, const fs::path& labs,
                        const fs::path& to, const std::string& labFolder,
                        const CourseSettings& course, Level level, SolutionText solution) {
    std::error_code ec;
    for (const HandoutStage& h : plan) {
        const fs::path from = labs / h.stage->id, stageTo = to / h.stage->id;
        // The open level's own files and guide; none at the guided level (labs/ has them).
        std::map<std::string, std::string> open =
            level == Level::Open ? labFolderFiles(*h.stage, Level::Open, solution)
                                 : std::map<std::string, std::string>{};
        // A guided guide without what needs the solution: from the stage's
        // guide.md (labs/ holds the one with it).
        if (level == Level::Guided && solution == SolutionText::LeaveOut &&
            fs::is_regular_file(h.stage->folder() / "guide.md", ec))
            open["README.md"] = stageGuide(*h.stage, level, h.stage->grading, solution);
        fs::create_directories(stageTo);
        // The guide and its pictures; the shader files the plan names.
        for (const auto& [name, picture] : labPictures(from, level))
            fs::copy_file(picture, stageTo / name);
        for (const std::string& name : h.files()) {
            const bool own =
                std::find(h.ownFiles.begin(), h.ownFiles.end(), name) != h.ownFiles.end();
            if (own && open.count(name)) writeTextFileAtomic(stageTo / name, open.at(name));
            else fs::copy_file(from / name, stageTo / name);
        }
        const bool guide = open.count("README.md") || fs::is_regular_file(from / "README.md", ec);
        if (guide)
            writeTextFileAtomic(
                stageTo / "README.md",
                withGradingSection(
                    handoutGuide(open.count("README.md") ? open.at("README.md")
                                                         : readTextFile(from / "README.md"),
                                 h, labFolder),
                    *h.stage, course.gradingOf(*h.stage), courseRulesSection(*h.stage, course)));
    }
    writeTextFileAtomic(to / "README.md", readme(plan));
}

fs::path newOutputFolder(const std::string& outDir) {
    if (outDir.empty()) throw Error("--out DIR is required");
    fs::path out = fs::path(outDir).lexically_normal();
    if (out.filename().empty() && out.has_parent_path()) out = out.parent_path();
    if (out.empty() || out == "." || out == "..")
        throw Error("--out " + outDir + ": give a new folder's name");
    std::error_code ec;
    if (fs::exists(out, ec) && !(fs::is_directory(out, ec) && fs::is_empty(out, ec)))
        throw Error("--out " + outDir + ": exists and is not an empty folder (nothing written)");
    const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    if (!fs::is_directory(parent, ec))
        throw Error("--out " + outDir + ": folder " + parent.string() + " does not exist");
    return out;
}

void writeWhole(const fs::path& out, const std::string& what,
                const std::function<void(const fs::path&)>& write) {
    const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    const fs::path temp =
        parent / ("." + out.filename().string() + ".tmp-" + std::to_string(getpid()));
    std::error_code ec;
    try {
        fs::create_directories(temp);
        write(temp);
        if (fs::exists(out, ec)) fs::remove(out);  // empty: newOutputFolder checked it
        fs::rename(temp, out);
    } catch (const fs::filesystem_error& e) {
        fs::remove_all(temp, ec);
        throw Error("cannot write " + what + ": " + std::string(e.what()));
    } catch (...) {
        fs::remove_all(temp, ec);
        throw;
    }
}

}  // namespace raylab
