// The child-process halves of `raylab grade`: render the reference images of
// one stage, or grade one stage of one submission. Each runs in its own
// process so that a submission's endless loop, crash or memory blow-up ends
// only that process (cmd_grade.cpp reports it and goes on).
#include "atomic_file.h"
#include "command.h"
#include "commands.h"
#include "course_file.h"
#include "error.h"
#include "gl_loader.h"
#include "grade_stage.h"

#include <cstdio>
#include <new>

namespace raylab {

int cmdGradeReference(const std::string& stageId, const std::string& outDir, unsigned seed) {
    const StageInfo& stage = findStage(stageId);
    auto context = createHeadlessContext(Backend::Auto);
    renderGradingReferences(stage, seed, outDir);
    writeTextFileAtomic(std::filesystem::path(outDir) / "reference" / "machine.txt",
                        glDescription() + "\n");
    return 0;
}

int cmdGradeItem(const std::string& stageId, const std::string& labRoot, const std::string& student,
                 const std::string& outDir, unsigned seed, const std::string& courseFile) {
    const StageInfo& stage = findStage(stageId);
    const std::filesystem::path resultFile =
        studentFolder(outDir, student) / stage.id / "result.json";
    try {
        auto context = createHeadlessContext(Backend::Auto);
        // The course's weights where it sets them (checked by the parent already).
        const CourseSettings course =
            courseFile.empty() ? CourseSettings{} : readCourseFile(courseFile);
        StageResult result = gradeStage(stage, course.gradingOf(stage), labRoot, student, outDir,
                                        seed, course.earlierStages);
        writeTextFileAtomic(resultFile, stageResultToJson(result));
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "raylab grade-item: out of memory\n");
        return 3;
    } catch (const Error& e) {
        // Bad input of the submission's own making (an #include that leaves
        // its folder, a missing file): scored 0 with the reason.
        StageResult result;
        result.stage = stage.id;
        result.status = "error";
        result.message = e.what();
        writeTextFileAtomic(resultFile, stageResultToJson(result));
    }
    return 0;
}

namespace {
struct ItemOptions {
    std::string stage, lab, student, out, course;
    unsigned seed = 0;
};
}  // namespace

Command gradeItemCommand() {
    return {"grade-item", "", [](CLI::App& cmd) {
                auto o = std::make_shared<ItemOptions>();
                cmd.add_option("--stage", o->stage)->required();
                cmd.add_option("--lab", o->lab)->required();
                cmd.add_option("--student", o->student)->required();
                cmd.add_option("--out", o->out)->required();
                cmd.add_option("--seed", o->seed);
                cmd.add_option("--course", o->course);
                return std::function<int()>([=] {
                    return cmdGradeItem(o->stage, o->lab, o->student, o->out, o->seed, o->course);
                });
            }};
}

Command gradeReferenceCommand() {
    return {"grade-reference", "", [](CLI::App& cmd) {
                auto o = std::make_shared<ItemOptions>();
                cmd.add_option("--stage", o->stage)->required();
                cmd.add_option("--out", o->out)->required();
                cmd.add_option("--seed", o->seed);
                return std::function<int()>(
                    [=] { return cmdGradeReference(o->stage, o->out, o->seed); });
            }};
}

}  // namespace raylab
