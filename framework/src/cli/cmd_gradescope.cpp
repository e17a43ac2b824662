// `raylab gradescope`: what the bundle's run_autograder runs on Gradescope
// (`raylab autograder` makes the bundle). Gradescope puts the student's
// upload in /autograder/submission and reads /autograder/results/results.json;
// the bundle's raylab-autograder.json holds the course's stages, secret seed
// and visibility settings. AUTOGRADER_ROOT (or --root) stands for
// /autograder, so the tests run it against a temporary folder.
#include "atomic_file.h"
#include "command.h"
#include "commands.h"
#include "error.h"
#include "grade_report.h"
#include "json_reader.h"
#include "upload_grading.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace raylab {

namespace fs = std::filesystem;

namespace {

struct GsOptions {
    std::string root;
    std::string config;
};

// raylab-autograder.json, as `raylab autograder` writes it.
struct BundleConfig {
    UploadGradeOptions grading;
    GradescopeOptions report;
};

BundleConfig readBundleConfig(const fs::path& file) {
    const json doc = parseJsonFile(file, file.string());
    const JsonReader r{file.string()};
    r.allowOnly(doc, "config",
                {"stages", "seed", "visibility", "test_visibility", "seeded_visibility",
                 "stdout_visibility", "timeout_s", "memory_mb", "level"});
    BundleConfig c;
    const json& stages = r.member(doc, "config", "stages");
    if (!stages.is_array() || stages.empty()) r.fail("stages", "expected a list of stage ids");
    for (const json& s : stages) c.grading.stages.push_back(findStage(r.string(s, "stages")).id);
    const json& seed = r.member(doc, "config", "seed");
    if (!seed.is_number_unsigned() || seed.get<std::uint64_t>() > 0xffffffffu)
        r.fail("seed", "expected a whole number from 0 to 4294967295");
    c.grading.seed = seed.get<unsigned>();
    auto visibility = [&](const char* key, std::string& into) {
        if (!doc.contains(key)) return;
        into = r.string(doc[key], key);
        if (!isGradescopeVisibility(into))
            r.fail(key, "expected visible, hidden, after_due_date or after_published");
    };
    if (doc.contains("level")) {
        try {
            c.grading.level = parseLevel(r.string(doc["level"], "level"));
        } catch (const Error&) { r.fail("level", "expected guided or open"); }
    }
    visibility("visibility", c.report.visibility);
    visibility("test_visibility", c.report.testVisibility);
    visibility("seeded_visibility", c.report.seededVisibility);
    visibility("stdout_visibility", c.report.stdoutVisibility);
    if (doc.contains("timeout_s"))
        c.grading.timeoutSeconds = r.positive(doc["timeout_s"], "timeout_s");
    if (doc.contains("memory_mb")) {
        // 0 is "no limit", as `raylab autograder --memory-mb 0` writes it.
        const float mb = r.number(doc["memory_mb"], "memory_mb");
        if (mb < 0) r.fail("memory_mb", "expected 0 (no limit) or a positive number");
        c.grading.memoryMb = long(mb);
    }
    return c;
}

int cmdGradescope(const GsOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    const char* env = std::getenv("AUTOGRADER_ROOT");
    const fs::path root =
        !o.root.empty() ? fs::path(o.root) : fs::path(env && *env ? env : "/autograder");
    const fs::path config =
        !o.config.empty() ? fs::path(o.config) : root / "source" / "raylab-autograder.json";
    const fs::path results = root / "results" / "results.json";
    std::error_code ec;
    fs::remove(results, ec);  // no result of an earlier run may pass for this one's
    fs::create_directories(results.parent_path(), ec);
    if (ec) throw Error("cannot create " + results.parent_path().string() + ": " + ec.message());
    auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };

    try {
        const BundleConfig c = readBundleConfig(config);
        UploadGrade graded = gradeUpload(root / "submission", root / "raylab-work", c.grading);
        GradescopeOptions report = c.report;
        report.seconds = seconds();
        for (const std::string& n : graded.layout.notes) report.notes += n + "\n";
        StudentResult student;
        if (graded.student) {
            student = *graded.student;
        } else {
            // Not gradable: every stage scores 0, and says why.
            for (const std::string& id : c.grading.stages) {
                StageResult s;
                s.stage = id;
                s.status = graded.layout.empty ? "not submitted" : "error";
                s.message = graded.layout.problem;
                student.stages.push_back(s);
            }
        }
        // Messages name the student's own files, not the grader's copy.
        for (StageResult& s : student.stages) {
            s.message = graded.shown(s.message);
            for (CheckResult& k : s.checks) k.output = graded.shown(k.output);
        }
        writeTextFileAtomic(results, gradescopeJson(student, report));
        std::printf("raylab gradescope: %.2f / %.2f; wrote %s\n", student.score(),
                    student.maxScore(), results.c_str());
        return 0;
    } catch (const std::exception& e) {
        // The bundle or the grader failed, not the student: a valid file
        // that says so (score 0), and the cause in the log for the staff.
        using Json = nlohmann::ordered_json;
        const Json j{{"score", 0.0},
                     {"execution_time", std::lround(seconds())},
                     {"output", "The autograder could not grade this submission (" +
                                    std::string(e.what()) +
                                    "). Please tell your instructor; this is not your mistake."},
                     {"visibility", "visible"},
                     {"stdout_visibility", "hidden"},
                     {"tests", Json::array()}};
        writeTextFileAtomic(results,
                            j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
        throw;
    }
}

}  // namespace

Command gradescopeCommand() {
    return {
        "gradescope",
        "Gradescope autograder (run_autograder of `raylab autograder`'s bundle): grade "
        "/autograder/submission into /autograder/results/results.json (AUTOGRADER_ROOT "
        "overrides /autograder)",
        [](CLI::App& cmd) {
            auto o = std::make_shared<GsOptions>();
            cmd.add_option("--root", o->root,
                           "in place of /autograder (default: $AUTOGRADER_ROOT or /autograder)");
            cmd.add_option("--config", o->config,
                           "the bundle's settings (default: ROOT/source/raylab-autograder.json)");
            return std::function<int()>([=] { return cmdGradescope(*o); });
        }};
}

}  // namespace raylab
