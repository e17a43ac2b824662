// `raylab handout --stages 01-03 --out DIR`: the labs students may have now.
// A stage folder holds its own files in lab form; the files of the stages
// it builds on are read from the student's own folders of those stages
// (course/handout.h says what goes where), so a handout never holds the
// solution of a stage it hands out. `--carry solved` puts the earlier stages
// this handout does not release in, solved. The folder appears whole or not
// at all (written beside it, then renamed).
#include "atomic_file.h"
#include "command.h"
#include "course_file.h"
#include "error.h"
#include "handout.h"
#include "paths.h"
#include "stage_list.h"
#include "stage_sources.h"

#include <cstdio>
#include <unistd.h>

namespace raylab {

namespace fs = std::filesystem;

namespace {

bool isShaderFile(const fs::path& p) {
    const std::string e = p.extension().string();
    return e == ".glsl" || e == ".frag" || e == ".vert" || e == ".geom";
}

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

// --out as given, without a trailing separator ("week3/" is the folder week3).
fs::path outFolder(const std::string& outDir) {
    fs::path out = fs::path(outDir).lexically_normal();
    if (out.filename().empty() && out.has_parent_path()) out = out.parent_path();
    return out;
}

int cmdHandout(const std::string& list, const std::string& outDir, const std::string& labDir,
               const std::string& carryName, const std::string& courseFile) {
    if (outDir.empty()) throw Error("--out DIR is required");
    const Carry carry = parseCarry(carryName);
    // The guides' "How you are graded" with the course's weights.
    const CourseSettings course =
        courseFile.empty() ? CourseSettings{} : readCourseFile(courseFile);
    const std::vector<HandoutStage> plan = planHandout(parseStageList(list), carry);
    const fs::path labs = labDir.empty() ? defaultLabRoot() : fs::path(labDir);
    const fs::path out = outFolder(outDir);
    if (out.empty() || out == "." || out == "..")
        throw Error("--out " + outDir + ": give a new folder's name");
    std::error_code ec;
    for (const HandoutStage& h : plan)
        for (const std::string& name : h.files())
            if (!fs::is_regular_file(labs / h.stage->id / name, ec))
                throw Error("lab file " + (labs / h.stage->id / name).string() +
                            " does not exist (regenerate labs/ with raylab-labgen)");
    if (fs::exists(out, ec) && !(fs::is_directory(out, ec) && fs::is_empty(out, ec)))
        throw Error("--out " + outDir + ": exists and is not an empty folder (nothing written)");
    const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    if (!fs::is_directory(parent, ec))
        throw Error("--out " + outDir + ": folder " + parent.string() + " does not exist");

    // How the guides' commands name the handout: as --out did, from the RayLab folder.
    const std::string labFolder = out.generic_string() + "/";
    const fs::path temp =
        parent / ("." + out.filename().string() + ".tmp-" + std::to_string(getpid()));
    try {
        fs::create_directories(temp);
        for (const HandoutStage& h : plan) {
            const fs::path from = labs / h.stage->id, to = temp / h.stage->id;
            fs::create_directories(to);
            // The guide and its pictures; the shader files the plan names.
            for (const fs::directory_entry& e : fs::directory_iterator(from)) {
                const std::string name = e.path().filename().string();
                if (!e.is_regular_file() || isShaderFile(e.path()) || name == "README.md") continue;
                fs::copy_file(e.path(), to / name);
            }
            for (const std::string& name : h.files()) fs::copy_file(from / name, to / name);
            if (fs::is_regular_file(from / "README.md", ec))
                writeTextFileAtomic(
                    to / "README.md",
                    withGradingSection(handoutGuide(readTextFile(from / "README.md"), h, labFolder),
                                       *h.stage, course.gradingOf(*h.stage)));
        }
        writeTextFileAtomic(temp / "README.md", readme(plan));
        if (fs::exists(out, ec)) fs::remove(out);  // the empty folder checked above
        fs::rename(temp, out);
    } catch (const fs::filesystem_error& e) {
        fs::remove_all(temp, ec);
        throw Error("cannot write the handout: " + std::string(e.what()));
    } catch (...) {
        fs::remove_all(temp, ec);
        throw;
    }
    std::string ids;
    bool reads = false;
    for (const HandoutStage& h : plan) {
        ids += (ids.empty() ? "" : ", ") + h.stage->id;
        reads = reads || !h.fromStudent.empty();
    }
    std::printf("raylab handout: wrote %s with %zu stage%s (%s): no solution of a stage it hands "
                "out%s\n",
                out.c_str(), plan.size(), plan.size() == 1 ? "" : "s", ids.c_str(),
                reads ? "; earlier stages' files are read from the student's own stage folders"
                      : "");
    return 0;
}

}  // namespace

Command handoutCommand() {
    return {"handout",
            "write the lab folders of the released stages, for students: each stage's own files "
            "in lab form, no solution of a stage it hands out",
            [](CLI::App& cmd) {
                auto stages = std::make_shared<std::string>();
                auto out = std::make_shared<std::string>();
                auto labs = std::make_shared<std::string>();
                auto carry = std::make_shared<std::string>("own");
                auto course = std::make_shared<std::string>();
                cmd.add_option("--stages", *stages,
                               "the released stages: a range within a track (01-03, f1-f2), a "
                               "list (01,02,f1), both (01-03,f1) or all")
                    ->required();
                cmd.add_option("--out", *out, "the folder to write (new, or empty)")->required();
                cmd.add_option("--labs", *labs, "the labs to copy from (default: labs/)");
                cmd.add_option("--carry", *carry,
                               "earlier stages this handout does not release: own (read from "
                               "the student's own folders) or solved (put in, solved: for a "
                               "course that releases a stage's solution after its deadline)")
                    ->capture_default_str();
                cmd.add_option("--course", *course,
                               "a course file (docs/grading.md): the guides show its weights");
                return std::function<int()>(
                    [=] { return cmdHandout(*stages, *out, *labs, *carry, *course); });
            }};
}

}  // namespace raylab
