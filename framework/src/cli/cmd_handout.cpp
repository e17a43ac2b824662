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
#include "handout_folder.h"
#include "paths.h"
#include "stage_list.h"
#include "stage_sources.h"

#include <cstdio>

namespace raylab {

namespace fs = std::filesystem;

namespace {

int cmdHandout(const std::string& list, const std::string& outDir, const std::string& labDir,
               const std::string& carryName, const std::string& courseFile,
               const std::string& levelName) {
    const Carry carry = parseCarry(carryName);
    const Level level = parseLevel(levelName);
    // The guides' "How you are graded" with the course's weights.
    const CourseSettings course =
        courseFile.empty() ? CourseSettings{} : readCourseFile(courseFile);
    const std::vector<HandoutStage> plan = planHandout(parseStageList(list), carry);
    const fs::path labs = labDir.empty() ? defaultLabRoot() : fs::path(labDir);
    const fs::path out = newOutputFolder(outDir);
    checkHandoutSources(plan, labs);
    // How the guides' commands name the handout: as --out did, from the RayLab folder.
    const std::string labFolder = out.generic_string() + "/";
    writeWhole(out, "the handout", [&](const fs::path& to) {
        writeHandoutFolder(plan, labs, to, labFolder, course, level);
    });
    std::string ids;
    bool reads = false;
    for (const HandoutStage& h : plan) {
        ids += (ids.empty() ? "" : ", ") + h.stage->id;
        reads = reads || !h.fromStudent.empty();
    }
    std::printf("raylab handout: wrote %s with %zu stage%s (%s) at the %s level: no solution of a "
                "stage it hands out%s\n",
                out.c_str(), plan.size(), plan.size() == 1 ? "" : "s", ids.c_str(),
                raylab::levelName(level),
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
                auto level = std::make_shared<std::string>("guided");
                cmd.add_option("--stages", *stages,
                               "the released stages: a range within a track (01-03, f1-f2), a "
                               "list (01,02,f1), both (01-03,f1) or all")
                    ->required();
                cmd.add_option("--out", *out, "the folder to write (new, or empty)")->required();
                cmd.add_option("--labs", *labs,
                               "the labs to copy from (default: labs/); at the open level only "
                               "their pictures and earlier stages' solved files");
                cmd.add_option("--level", *level,
                               "guided (labs/: the algorithm's structure given) or open (whole "
                               "functions written from their contracts)")
                    ->capture_default_str();
                cmd.add_option("--carry", *carry,
                               "earlier stages this handout does not release: own (read from "
                               "the student's own folders) or solved (put in, solved: for a "
                               "course that releases a stage's solution after its deadline)")
                    ->capture_default_str();
                cmd.add_option("--course", *course,
                               "a course file (docs/grading.md): the guides show its weights");
                return std::function<int()>(
                    [=] { return cmdHandout(*stages, *out, *labs, *carry, *course, *level); });
            }};
}

}  // namespace raylab
