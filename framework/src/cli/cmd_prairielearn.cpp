// `raylab prairielearn`: the entry point of a PrairieLearn external grader
// (examples/prairielearn/). PrairieLearn puts the student's files in
// /grade/student and reads /grade/results/results.json: the score from 0 to
// 1, whether the submission was gradable, one test per check with its
// points and message, and the difference heat maps of failed views as
// images (the file must stay under 1 MB). GRADE_ROOT (or --root) stands for
// /grade, so the tests run it against a temporary folder.
#include "atomic_file.h"
#include "command.h"
#include "commands.h"
#include "error.h"
#include "paths.h"
#include "upload_grading.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// Pictures in results.json, base64 inside a data URL, within this budget
// (PrairieLearn's limit for the whole file is 1 MB).
constexpr std::size_t kImageBudget = 600 * 1024;

std::string base64(const std::string& bytes) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                           (unsigned char)bytes[i + 2];
        for (int k = 18; k >= 0; k -= 6) out += abc[(v >> k) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = (unsigned char)bytes[i] << 16;
        if (i + 1 < bytes.size()) v |= (unsigned char)bytes[i + 1] << 8;
        out += abc[(v >> 18) & 63];
        out += abc[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? abc[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

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
    std::string notes;
    for (const std::string& n : graded.layout.notes) notes += n + "\n";
    const std::string& problem = graded.layout.problem;
    if (!problem.empty())  // not gradable: no attempt is used up
        return write(Json{{"gradable", false},
                          {"score", 0.0},
                          {"format_errors", Json::array({problem})},
                          {"message", problem},
                          {"output", notes}});
    const StudentResult& st = *graded.student;
    auto shown = [&](const std::string& text) { return graded.shown(text); };
    std::error_code ec;

    Json tests = Json::array();
    std::size_t imageBytes = 0;
    std::string summary;
    for (const StageResult& s : st.stages) {
        summary += (summary.empty() ? "" : "; ") + s.stage + ": " +
                   (s.status == "graded" ? std::to_string(int(s.score + 0.5)) + "/" +
                                               std::to_string(int(s.maxScore + 0.5))
                                         : s.status);
        if (s.status != "graded" || s.checks.empty()) {
            tests.push_back(Json{{"name", s.stage},
                                 {"description", s.status},
                                 {"points", s.score},
                                 {"max_points", s.maxScore},
                                 {"message", shown(s.message.empty() ? s.status : s.message)}});
            continue;
        }
        // PrairieLearn shows every test of results.json at once (its tests
        // have no visibility of their own, unlike Gradescope's). Hidden
        // seeded views are one test: their points count (the score is the
        // grade), but not which view failed, how, or its picture.
        double seededPoints = 0, seededMax = 0;
        int seededCount = 0;
        for (const CheckResult& c : s.checks) {
            if (c.seeded && o.seededViews == "hidden") {
                seededPoints += c.score;
                seededMax += c.maxScore;
                ++seededCount;
                continue;
            }
            Json t{{"name", s.stage + " / " + c.name},
                   {"description", c.kind == "image" ? "a camera view against the solution"
                                                     : "a function against a reference"},
                   {"points", c.score},
                   {"max_points", c.maxScore},
                   {"message", shown(c.output)}};
            // The difference heat map of a failed view, while the budget lasts.
            if (!c.passed && !c.diffImage.empty()) {
                const fs::path png = graded.outDir / c.diffImage;
                if (fs::is_regular_file(png, ec)) {
                    const std::string url = "data:image/png;base64," + base64(readTextFile(png));
                    if (imageBytes + url.size() <= kImageBudget) {
                        imageBytes += url.size();
                        t["images"] = Json::array(
                            {Json{{"label", c.name + ": difference (black equal, red most)"},
                                  {"url", url}}});
                    }
                }
            }
            tests.push_back(t);
        }
        if (seededCount > 0)
            tests.push_back(
                Json{{"name", s.stage + " / " + std::to_string(seededCount) + " further views"},
                     {"description", "camera views moved a little from the check views"},
                     {"points", seededPoints},
                     {"max_points", seededMax},
                     {"message", "Which of these views differ, and how, is shown after the due "
                                 "date: the views are drawn from the course's secret seed, so "
                                 "that a lab passes them by being right, not by matching a "
                                 "picture."}});
    }
    const double max = st.maxScore();
    return write(Json{{"gradable", true},
                      {"score", max > 0 ? st.score() / max : 0.0},
                      {"message", "Total " + std::to_string(int(st.score() + 0.5)) + " / " +
                                      std::to_string(int(max + 0.5)) + ". " + summary},
                      {"output", notes},
                      {"tests", tests}});
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
