#include "check_report.h"
#include "check_sandbox.h"
#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "course_file.h"
#include "error.h"
#include "function_harness.h"
#include "image_compare.h"
#include "lab_folder.h"
#include "paths.h"
#include "stage_score.h"
#include "view_renderers.h"

#include <algorithm>
#include <cstdio>

namespace raylab {

namespace {

// The grader's rule for views the lab as handed out draws (stage_score.h):
// a failing picture equal to the handed-out lab's earns nothing, and a view
// the handed-out lab draws right reaches none of the stage's code. Drawn only
// when a view fails (with every view passing, neither rule changes a point).
void markHandedOutViews(const StageInfo& stage, const std::vector<CheckView>& views,
                        const std::string& scene, int w, int h, const SceneTransform& transform,
                        const std::vector<Image>& mine, const std::vector<Image>& expected,
                        const std::vector<bool>& viewPassed, std::vector<CheckCredit>& credits) {
    const std::size_t firstView = credits.size() - mine.size();
    if (std::all_of(viewPassed.begin(), viewPassed.end(), [](bool p) { return p; })) return;
#ifdef RAYLAB_STUDENT_BUILD
    // The handed-out lab's pictures as grading draws them (the earlier
    // stages solved), shipped as data: the repository has no earlier
    // stage's solution to draw them with (`raylab student-repo`).
    (void)scene, (void)w, (void)h, (void)transform;
    try {
        const std::filesystem::path dir = projectRoot() / "course" / "handed-out" / stage.id;
        for (std::size_t i = 0; i < mine.size(); ++i)
            creditHandedOutView(credits[firstView + i], viewPassed[i], mine[i], expected[i],
                                loadPng(dir / (views[i].name + ".png")));
    } catch (const Error&) {  // no pictures to compare with: grading counts every view
    }
#else
    try {
        ViewRenderers handedOut(stage, labSources(stage, handedOutLabRoot()), scene, w, h,
                                transform);
        for (std::size_t i = 0; i < mine.size(); ++i)
            creditHandedOutView(credits[firstView + i], viewPassed[i], mine[i], expected[i],
                                handedOut.render(views[i]));
    } catch (const Error&) {  // no handed-out lab to compare with: grading counts every view
    }
#endif
}

// The checks a run does, of each kind (raylab check --checks).
struct SelectedChecks {
    std::vector<CheckView> views;
    std::vector<const FunctionSpec*> functions;
    std::vector<std::string> counts;
};

// The stage's checks that ONLY names (all when it is empty); throws Error for
// a name the stage has no check of.
SelectedChecks selectChecks(const StageInfo& stage, const std::vector<std::string>& only) {
    auto wanted = [&](const std::string& name) {
        return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
    };
    SelectedChecks s;
    std::vector<std::string> names;
    for (const CheckView& v : stage.checkViews) {
        names.push_back(v.name);
        if (wanted(v.name)) s.views.push_back(v);
    }
    for (const FunctionSpec* f : functionSpecsFor(stage)) {
        names.push_back(f->name);
        if (wanted(f->name)) s.functions.push_back(f);
    }
    for (const std::string& c : stage.countChecks) {
        names.push_back(c);
        if (wanted(c)) s.counts.push_back(c);
    }
    for (const std::string& name : only)
        if (std::find(names.begin(), names.end(), name) == names.end()) {
            std::string list;
            for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
            throw Error("--checks: stage " + stage.id + " has no check '" + name +
                        "' (its checks: " + list + ")");
        }
    return s;
}

}  // namespace

int cmdCheck(const StageOptions& options, const CheckOptions& check) {
    StageSetup setup = resolveStageOptions(options);
    const StageInfo& stage = *setup.stage;
    const CourseSettings course =
        check.courseFile.empty() ? CourseSettings{} : readCourseFile(check.courseFile);
    const StageGrading& grading = course.gradingOf(stage);
    const SelectedChecks selected = selectChecks(stage, check.only);  // a bad name: said here
    // The work runs in a child, as grading runs it: a crash or an endless
    // compile becomes a one-line cause (check_sandbox.h).
    if (!insideCheckSandbox())
        return runCheckInSandbox(stage, setup.sources.labRoot,
                                 {check.timeoutSeconds, check.memoryMb, check.backend});
#ifdef RAYLAB_STUDENT_BUILD
    // No solution to render here: the reference pictures the repository
    // ships (`raylab student-repo`), drawn at the check's own size.
    const std::filesystem::path against = check.againstDir.empty()
                                              ? projectRoot() / "course" / "references" / stage.id
                                              : std::filesystem::path(check.againstDir);
    if (check.againstDir.empty()) {
        if (setup.size.width != 160 || setup.size.height != 120)
            throw Error("--size " + options.size +
                        ": this repository's reference pictures are 160x120 (leave --size out)");
        if (!options.scene.empty() || !setup.transform.identity())
            throw Error("--scene, --scene-scale and --scene-offset need pictures of the solution, "
                        "which this repository does not hold (its references are of the "
                        "stage's own views)");
    }
#else
    const std::filesystem::path against = check.againstDir;
#endif
    std::error_code ec;
    if (!against.empty() && !std::filesystem::is_directory(against, ec))
        throw Error("--against '" + check.againstDir + "': folder does not exist");
    if (!check.saveDir.empty()) {
        std::filesystem::create_directories(check.saveDir, ec);
        if (ec) throw Error("--save '" + check.saveDir + "': cannot create the folder");
    }

    auto context = createHeadlessContext(check.backend);
    const int w = setup.size.width, h = setup.size.height;
    // Frames read as grading reads them (view_renderers.h).
    // With --scene-scale / --scene-offset every view's scene and camera are
    // transformed: the pictures must still match the references.
    ViewRenderers students(stage, setup.sources, options.scene, w, h, setup.transform);
    std::unique_ptr<ViewRenderers> references;
    if (against.empty())
        references = std::make_unique<ViewRenderers>(stage, solutionSources(stage), options.scene,
                                                     w, h, setup.transform);
    const std::vector<OpenTodo> todos =
        students.forView(stage.checkViews.front()).openTodos();  // a compile error stops here
    reportOpenTodos(todos);
    // An earlier stage's file of the student's own that this stage reads and
    // that fails that stage's function check: said first, as it is the
    // cause of what fails below (earlier_stage_checks.h).
    const std::string labArg =
        options.labDir.empty() ? "" : " --lab " + displayPath(setup.sources.labRoot);
    std::fputs(formatEarlierFailures(stage, runEarlierFunctionChecks(stage, setup.sources), labArg)
                   .c_str(),
               stdout);

    std::printf("raylab check: stage %s, %s against %s, %dx%d, %s backend\n", stage.id.c_str(),
                setup.sources.label.c_str(),
                against.empty() ? "the solution rendered here" : displayPath(against).c_str(), w, h,
                context->backendName().c_str());
    // The wording is check_report.h's, shared with the page.
    int passed = 0, failed = 0;
    // Function checks first: a failing one names the one input, the
    // expected and the actual value, the cheapest hint there is.
    const auto& functions = selected.functions;
    if (!functions.empty()) std::fputs(formatFunctionsHeading().c_str(), stdout);
    std::vector<std::string> failedFunctions;
    std::vector<const FunctionSpec*> failedSpecs;
    // The grader's points for these checks: the check views, then the
    // function and count checks (stage_grading.h, stage_score.h).
    std::vector<std::string> viewWeights, otherNames;
    for (const CheckView& v : selected.views) viewWeights.push_back(v.name);
    for (const FunctionSpec* f : functions) otherNames.push_back(f->name);
    for (const std::string& c : selected.counts) otherNames.push_back(c);
    const std::vector<double> points = checkPoints(grading, viewWeights, otherNames);
    std::vector<CheckCredit> credits;
    for (const FunctionSpec* spec : functions) {
        FunctionOutcome f = runFunctionCheck(*spec, stage, setup.sources);
        bool ok = f.passed == f.total;
        (ok ? passed : failed) += 1;
        std::fputs(formatFunctionLine(f, !failedFunctions.empty()).c_str(), stdout);
        if (!ok) {
            std::fputs(formatReadsFailedNote(*spec, failedSpecs).c_str(), stdout);
            failedFunctions.push_back(f.name);
            failedSpecs.push_back(spec);
        }
        credits.push_back(
            {false, points[selected.views.size() + credits.size()], wrongShare(f.passed, f.total)});
    }
    std::fputs(formatViewsHeading().c_str(), stdout);
    std::vector<Image> mineOf, expectedOf;  // for the score's handed-out comparison
    std::vector<bool> viewPassed;
    for (const CheckView& view : selected.views) {
        long nonFinite = 0, todoPixels = 0;
        Image mine = students.render(view, &nonFinite, &todoPixels);
        Image expected;
        if (references) {
            expected = references->render(view);
        } else {
            expected = loadPng(against / (view.name + ".png"));
        }
        if (!check.saveDir.empty())
            writePngAtomic(mine, std::filesystem::path(check.saveDir) / (view.name + ".png"));
        const ViewOutcome v =
            judgeView(stage, view, mine, expected, nonFinite, todoPixels, !failedFunctions.empty());
        (v.passed ? passed : failed) += 1;
        std::fputs(formatViewLines(v, failedFunctions, todos.size()).c_str(), stdout);
        credits.push_back({true, points[mineOf.size()], v.diff.badShare, nonFinite > 0});
        viewPassed.push_back(v.passed);
        mineOf.push_back(std::move(mine));
        expectedOf.push_back(std::move(expected));
    }
    markHandedOutViews(stage, selected.views, options.scene, w, h, setup.transform, mineOf,
                       expectedOf, viewPassed, credits);

    for (const std::string& name : selected.counts) {
        // Counted from the check views' cameras: a number the GPU produced
        // against the same number worked out on the CPU.
        CountOutcome c = runCountCheck(students, name, stage.checkViews);
        (countPassed(c) ? passed : failed) += 1;
        std::fputs(formatCountLine(c).c_str(), stdout);
        credits.push_back({false, points[credits.size()], wrongShare(c.passed, c.total)});
    }
    std::fputs(formatSummary(passed, failed).c_str(), stdout);
    std::fputs(formatScoreLine(scoreChecks(credits), grading.seededViews).c_str(), stdout);
    return failed == 0 ? 0 : 1;
}

#ifdef RAYLAB_STUDENT_BUILD
constexpr const char* kCheckAbout =
    "check a stage against the course's reference pictures and expected values";
#else
constexpr const char* kCheckAbout = "check a stage against the solution from several camera views";
#endif

Command checkCommand() {
    return {"check", kCheckAbout, [](CLI::App& cmd) {
                auto stage = std::make_shared<StageOptions>();
                auto check = std::make_shared<CheckOptions>();
                stage->size = "160x120";
                CLI::Option* lab = addStageOptions(cmd, *stage, false);
                addSceneTransformOptions(cmd, *stage);
                cmd.add_option("--against", check->againstDir,
                               "compare with DIR/<view>.png instead of the solution rendered now");
                cmd.add_option("--save", check->saveDir,
                               "write the checked images to DIR/<view>.png");
                cmd.add_option("--timeout", check->timeoutSeconds,
                               "stop the check after this many seconds (default 600)")
                    ->check(CLI::PositiveNumber);
                cmd.add_option("--course", check->courseFile,
                               "score with a course file's weights (raylab grade --course)");
                cmd.add_option("--checks", check->only,
                               "comma-separated: run only these checks, by the names the report "
                               "prints (views, function and count checks; default: all)")
                    ->delimiter(',');
                cmd.add_option("--memory-mb", check->memoryMb,
                               "limit the check's address space, as grading does (default: none)")
                    ->check(CLI::NonNegativeNumber);
                auto backend = std::make_shared<BackendOption>(cmd);
                return std::function<int()>([=] {
                    check->backend = backend->resolve();
                    stage->labGiven = lab->count() > 0;
                    return cmdCheck(*stage, *check);
                });
            }};
}

}  // namespace raylab
