#include "grade_stage.h"

#include "check_report.h"
#include "error.h"
#include "function_harness.h"
#include "grade_views.h"
#include "image_compare.h"
#include "lab_folder.h"
#include "paths.h"
#include "shader_program.h"
#include "stage_score.h"
#include "stage_setup.h"
#include "stage_sources.h"
#include "view_renderers.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// Beside a stage's reference pictures: the handed-out lab's, from the same views.
constexpr const char* kUntouchedFolder = "untouched";

std::string relativeTo(const fs::path& p, const fs::path& base) {
    return p.lexically_relative(base).generic_string();
}

}  // namespace

void renderGradingReferences(const StageInfo& stage, unsigned seed, const fs::path& outDir) {
    const fs::path dir = outDir / "reference" / stage.id;
    fs::create_directories(dir);
    ViewRenderers renderers(stage, solutionSources(stage), "", kGradeWidth, kGradeHeight);
    for (const CheckView& view : gradingViews(stage, seed))
        writePngAtomic(renderers.render(view), dir / (view.name + ".png"));
    // The lab as handed out, from the same views: a view it already draws
    // right never reaches this stage's code and carries none of its points,
    // and a student's picture equal to it earns nothing (gradeStage).
    const fs::path untouched = dir / kUntouchedFolder;
    try {
        fs::create_directories(untouched);
        ViewRenderers lab(stage, labSources(stage, handedOutLabRoot()), "", kGradeWidth,
                          kGradeHeight);
        for (const CheckView& view : gradingViews(stage, seed))
            writePngAtomic(lab.render(view), untouched / (view.name + ".png"));
    } catch (const Error& e) {  // no lab to compare with: every view counts as before
        std::fprintf(stderr, "raylab: the handed-out lab of %s does not render (%s)\n",
                     stage.id.c_str(), e.what());
        std::error_code ec;
        fs::remove_all(untouched, ec);
    }
}

StageResult gradeStage(const StageInfo& stage, const StageGrading& grading, const fs::path& labRoot,
                       const std::string& student, const fs::path& outDir, unsigned seed,
                       EarlierStages earlier) {
    StageResult result;
    result.stage = stage.id;
    result.status = "graded";
    const fs::path refDir = outDir / "reference" / stage.id;
    const fs::path imageDir = studentFolder(outDir, student) / stage.id;
    fs::create_directories(imageDir);
    // Files the submission lacks (a stage folder without the earlier stage
    // folders it builds on) come from the lab as handed out: the stage is
    // graded on its own work, and the report says so.
    StageSources sources = labSources(stage, labRoot, MissingLabFiles::FromHandedOutLab, earlier);
    auto addMessage = [&](const std::string& line) {
        result.message += (result.message.empty() ? "" : "\n") + line;
    };
    if (!sources.filledIn.empty()) {
        std::string names;
        for (const std::string& n : sources.filledIn) names += (names.empty() ? "" : ", ") + n;
        addMessage("not in the submission, taken from the lab as handed out: " + names);
    }
    const std::vector<CheckView> views = gradingViews(stage, seed, grading.seededViews);
    const auto functions = functionSpecsFor(stage);
    // Every check's points, from the stage's weights (stage_grading.h).
    std::vector<std::string> viewWeights, otherNames;
    for (const CheckView& v : views) viewWeights.push_back(StageInfo::weightName(v));
    for (const FunctionSpec* f : functions) otherNames.push_back(f->name);
    for (const std::string& c : stage.countChecks) otherNames.push_back(c);
    const std::vector<double> points = checkPoints(grading, viewWeights, otherNames);
    auto pointsOfOther = [&](const std::string& name) {
        for (std::size_t i = 0; i < otherNames.size(); ++i)
            if (otherNames[i] == name) return points[views.size() + i];
        return 0.0;
    };

    std::vector<CheckResult> countResults;  // after the function checks in the report
    // The function checks first: a failing one is the evidence the views'
    // hints defer to (check_report.h). A harness that does not compile is
    // an outcome, not an exception.
    std::vector<FunctionOutcome> functionOutcomes;
    bool functionFailed = false;
    for (const FunctionSpec* spec : functions) {
        functionOutcomes.push_back(runFunctionCheck(*spec, stage, sources));
        functionFailed =
            functionFailed || functionOutcomes.back().passed < functionOutcomes.back().total;
    }
    try {
        ViewRenderers renderers(stage, sources, "", kGradeWidth, kGradeHeight);
        const CompareTolerance tolerance;
        for (const std::string& name : stage.countChecks) {
            CountOutcome c = runCountCheck(renderers, name, views);
            CheckResult check;
            check.name = c.name;
            check.kind = "count";
            check.maxScore = pointsOfOther(name);
            check.passed = c.total > 0 && c.passed == c.total;
            check.difference = wrongShare(c.passed, c.total);
            check.score = check.maxScore * caseCredit(check.difference);
            check.output = std::to_string(c.passed) + "/" + std::to_string(c.total) +
                           " views agree" +
                           (c.firstFailure.empty() ? "" : "; first failure: " + c.firstFailure);
            countResults.push_back(check);
        }
        // The handed-out lab's pictures of the same views (stage_score.h's
        // creditHandedOutView): a view that lab draws right reaches none of the
        // stage's code (a switch ignored still fails it), and its points are
        // scaled by the share the reaching views earned, so that an untouched
        // lab scores 0. Without them every view counts.
        const fs::path untouchedDir = refDir / kUntouchedFolder;
        std::vector<std::optional<Image>> untouched(views.size());
        for (std::size_t i = 0; i < views.size(); ++i) {
            const fs::path png = untouchedDir / (views[i].name + ".png");
            if (fs::exists(png)) untouched[i] = loadPng(png);
        }
        const std::size_t firstView = result.checks.size();
        std::vector<CheckCredit> viewCredits;
        for (std::size_t i = 0; i < views.size(); ++i) {
            const CheckView& view = views[i];
            CheckResult check;
            check.name = view.name;
            check.kind = "image";
            check.seeded = i >= stage.checkViews.size();  // gradingViews() appends them
            check.maxScore = points[i];
            long nonFinite = 0, todoPixels = 0;
            Image mine = renderers.render(view, &nonFinite, &todoPixels);
            Image expected = loadPng(refDir / (view.name + ".png"));
            ImageDiff diff = compareImages(mine, expected, tolerance.channel);
            check.passed = imagesAgree(diff, tolerance) && nonFinite == 0;
            check.difference = diff.badShare;
            CheckCredit credit{true, check.maxScore, diff.badShare, nonFinite > 0};
            if (untouched[i])
                creditHandedOutView(credit, check.passed, mine, expected, *untouched[i]);
            // Still the handed-out lab's picture: nothing of this view's work is done.
            const bool asHandedOut = credit.earnsNothing && nonFinite == 0;
            viewCredits.push_back(credit);
            check.output = describe(diff);
            if (asHandedOut) check.output += "; the same picture as the lab as handed out";
            if (nonFinite)
                check.output = std::to_string(nonFinite) +
                               " pixels are NaN or Inf (shown magenta); " + check.output;
            // The hint, in the words of `raylab check` (check_report.h).
            const std::string hint = check.passed ? ""
                                                  : judgeView(stage, view, mine, expected,
                                                              nonFinite, todoPixels, functionFailed)
                                                        .hint;
            if (!hint.empty()) check.output += "; " + hint;
            // What the view exercises points at the code to look at.
            if (!check.passed && !view.why.empty())
                check.output += "; this view checks: " + view.why;
            writePngAtomic(mine, imageDir / (view.name + ".png"));
            writePngAtomic(diffHeatMap(mine, expected), imageDir / (view.name + "-diff.png"));
            check.studentImage = relativeTo(imageDir / (view.name + ".png"), outDir);
            check.referenceImage = relativeTo(refDir / (view.name + ".png"), outDir);
            check.diffImage = relativeTo(imageDir / (view.name + "-diff.png"), outDir);
            result.checks.push_back(check);
        }
        // The scores, by the rule `raylab check` prints them by (stage_score.h).
        const StageScore score = scoreChecks(viewCredits);
        for (std::size_t i = 0; i < views.size(); ++i) {
            CheckResult& c = result.checks[firstView + i];
            c.score = viewCredits[i].score;
            if (viewCredits[i].reaches || score.reachShare >= 1.0) continue;
            c.passed = false;
            char note[160];
            std::snprintf(note, sizeof note,
                          "; this view does not reach the stage's code (the lab as handed out "
                          "draws it right): it earns %.0f%%, the share the other views earned",
                          100.0 * score.reachShare);
            c.output += note;
        }
    } catch (const ShaderError& e) {
        result.status = "compile error";
        result.message = e.log().empty() ? e.what() : e.log();
        result.checks.clear();
        result.score = 0;
        return result;
    }

    bool earlierFailed = false;  // a diagnosis only for the first failing function (check_report.h)
    for (const FunctionOutcome& f : functionOutcomes) {
        CheckResult check;
        check.name = f.name;
        check.kind = "function";
        check.maxScore = pointsOfOther(f.name);
        check.passed = f.total > 0 && f.passed == f.total;
        check.difference = wrongShare(f.passed, f.total);
        check.score = check.maxScore * caseCredit(check.difference);
        check.output = std::to_string(f.passed) + "/" + std::to_string(f.total) + " cases agree" +
                       (f.firstFailure.empty() ? "" : "; first failure: " + f.firstFailure) +
                       (f.cause.empty() || earlierFailed ? "" : "; hint: " + f.cause);
        earlierFailed = earlierFailed || !check.passed;
        result.checks.push_back(check);
    }
    for (CheckResult& c : countResults) result.checks.push_back(std::move(c));
    // Graded with the earlier stages solved: a slip there that this stage
    // would read from the student's own folder is named, so that the student
    // fixes it where it is (the slip costs points in its own stage only).
    if (sources.earlierSolved) {
        const StageSources own = labSources(stage, labRoot, MissingLabFiles::FromHandedOutLab);
        const std::string note = earlierFailuresNote(runEarlierFunctionChecks(stage, own));
        if (!note.empty()) addMessage(note);
    }
    for (const CheckResult& c : result.checks) result.score += c.score;
    result.score = std::round(result.score * 100.0) / 100.0;  // scoreChecks' rounding
    return result;
}

std::string stageResultToJson(const StageResult& r) {
    nlohmann::json j = {{"stage", r.stage},
                        {"status", r.status},
                        {"message", r.message},
                        {"score", r.score},
                        {"max_score", r.maxScore},
                        {"seconds", r.seconds},
                        {"checks", nlohmann::json::array()}};
    for (const CheckResult& c : r.checks)
        j["checks"].push_back({{"name", c.name},
                               {"kind", c.kind},
                               {"score", c.score},
                               {"max_score", c.maxScore},
                               {"passed", c.passed},
                               {"difference", c.difference},
                               {"seeded", c.seeded},
                               {"output", c.output},
                               {"student_image", c.studentImage},
                               {"reference_image", c.referenceImage},
                               {"diff_image", c.diffImage}});
    return j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace);
}

StageResult stageResultFromJson(const std::string& text) {
    try {
        nlohmann::json j = nlohmann::json::parse(text);
        StageResult r;
        r.stage = j.at("stage").get<std::string>();
        r.status = j.at("status").get<std::string>();
        r.message = j.at("message").get<std::string>();
        r.score = j.at("score").get<double>();
        r.maxScore = j.at("max_score").get<double>();
        r.seconds = j.at("seconds").get<double>();
        for (const auto& c : j.at("checks")) {
            CheckResult k;
            k.name = c.at("name").get<std::string>();
            k.kind = c.at("kind").get<std::string>();
            k.score = c.at("score").get<double>();
            k.maxScore = c.at("max_score").get<double>();
            k.passed = c.at("passed").get<bool>();
            k.seeded = c.value("seeded", false);  // shard files written before it existed
            k.difference = c.value("difference", 0.0);
            k.output = c.at("output").get<std::string>();
            k.studentImage = c.at("student_image").get<std::string>();
            k.referenceImage = c.at("reference_image").get<std::string>();
            k.diffImage = c.at("diff_image").get<std::string>();
            r.checks.push_back(k);
        }
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw Error(std::string("malformed grading result: ") + e.what());
    }
}

}  // namespace raylab
