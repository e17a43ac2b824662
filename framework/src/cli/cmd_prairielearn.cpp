// `raylab prairielearn`: the entry point of a PrairieLearn external grader
// (examples/prairielearn/). PrairieLearn puts the student's files in
// /grade/student and reads /grade/results/results.json
// (classroom/prairielearn_results.h). GRADE_ROOT (or --root) stands for
// /grade, so the tests run it against a temporary folder.
#include "atomic_file.h"
#include "command.h"
#include "commands.h"
#include "error.h"
#include "paths.h"
#include "prairielearn_results.h"
#include "upload_grading.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>

namespace raylab {

namespace fs = std::filesystem;

namespace {

struct PlOptions {
    std::string root;
    std::string stages;
    unsigned seed = 0;
    double timeoutSeconds = 60.0;
    long memoryMb = 2048;
    std::string level = "guided";
    std::string seededViews = "hidden";  // "shown": each seeded view as its own test
};

int cmdPrairieLearn(const PlOptions& o) {
    const char* env = std::getenv("GRADE_ROOT");
    const fs::path root =
        !o.root.empty() ? fs::path(o.root) : fs::path(env && *env ? env : "/grade");
    if (o.stages.empty()) throw Error("--stages is required (the stages this question grades)");
    const std::vector<std::string> stages = stageList(o.stages);
    const fs::path results = root / "results" / "results.json";
    fs::create_directories(results.parent_path());
    using Json = nlohmann::ordered_json;
    auto write = [&](const Json& j) {
        writeTextFileAtomic(results,
                            j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
        std::printf("raylab prairielearn: wrote %s\n", results.c_str());
        return 0;
    };

    const UploadGrade graded =
        gradeUpload(root / "student", root / "raylab-work",
                    {stages, o.seed, o.timeoutSeconds, o.memoryMb, parseLevel(o.level)});
    return write(prairieLearnResults(graded, o.seededViews == "hidden"));
}

}  // namespace

Command prairieLearnCommand() {
    return {"prairielearn",
            "PrairieLearn external grader: grade /grade/student into /grade/results/results.json "
            "(GRADE_ROOT overrides /grade)",
            [](CLI::App& cmd) {
                auto o = std::make_shared<PlOptions>();
                cmd.add_option("--stages", o->stages, "the stages this question grades, e.g. 03")
                    ->required();
                cmd.add_option("--root", o->root,
                               "in place of /grade (default: $GRADE_ROOT or /grade)");
                cmd.add_option("--seed", o->seed, "seed of the extra camera views (keep it secret)")
                    ->capture_default_str();
                cmd.add_option("--timeout", o->timeoutSeconds, "seconds per stage")
                    ->capture_default_str();
                cmd.add_option("--memory-mb", o->memoryMb, "address-space limit per stage, MB")
                    ->capture_default_str();
                cmd.add_option("--level", o->level,
                               "the level of the labs handed out: guided or open (raylab "
                               "handout --level)")
                    ->capture_default_str();
                cmd.add_option("--seeded-views", o->seededViews,
                               "hidden: the seeded views count but are one test without "
                               "details (PrairieLearn shows every test at once); shown: each "
                               "its own test, e.g. for a regrade after the due date")
                    ->check(CLI::IsMember({"hidden", "shown"}))
                    ->capture_default_str();
                return std::function<int()>([=] { return cmdPrairieLearn(*o); });
            }};
}

}  // namespace raylab
