#include "check_report.h"
#include "check_sandbox.h"
#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "error.h"
#include "function_harness.h"
#include "image_compare.h"
#include "paths.h"
#include "view_renderers.h"

#include <cstdio>

namespace raylab {

int cmdCheck(const StageOptions& options, const CheckOptions& check) {
    StageSetup setup = resolveStageOptions(options);
    const StageInfo& stage = *setup.stage;
    // The work runs in a child, as grading runs it: a crash or an endless
    // compile becomes a one-line cause (check_sandbox.h).
    if (!insideCheckSandbox())
        return runCheckInSandbox(stage, setup.sources.labRoot,
                                 {check.timeoutSeconds, check.memoryMb, check.backend});
    const std::filesystem::path against = check.againstDir;
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

    std::printf("raylab check: stage %s, %s against %s, %dx%d, %s backend\n", stage.id.c_str(),
                setup.sources.label.c_str(),
                against.empty() ? "the solution rendered here" : displayPath(against).c_str(), w, h,
                context->backendName().c_str());
    // The wording is check_report.h's, shared with the page.
    int passed = 0, failed = 0;
    // Function checks first: a failing one names the one input, the
    // expected and the actual value, the cheapest hint there is.
    const auto functions = functionSpecsFor(stage);
    if (!functions.empty()) std::fputs(formatFunctionsHeading().c_str(), stdout);
    std::vector<std::string> failedFunctions;
    for (const FunctionSpec* spec : functions) {
        FunctionOutcome f = runFunctionCheck(*spec, stage, setup.sources);
        bool ok = f.passed == f.total;
        (ok ? passed : failed) += 1;
        if (!ok) failedFunctions.push_back(f.name);
        std::fputs(formatFunctionLine(f).c_str(), stdout);
    }
    std::fputs(formatViewsHeading().c_str(), stdout);
    for (const CheckView& view : stage.checkViews) {
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
        const ViewOutcome v = judgeView(stage, view, mine, expected, nonFinite, todoPixels);
        (v.passed ? passed : failed) += 1;
        std::fputs(formatViewLines(v, failedFunctions, todos.size()).c_str(), stdout);
    }

    for (const std::string& name : stage.countChecks) {
        // Counted from the check views' cameras: a number the GPU produced
        // against the same number worked out on the CPU.
        CountOutcome c = runCountCheck(students, name, stage.checkViews);
        (countPassed(c) ? passed : failed) += 1;
        std::fputs(formatCountLine(c).c_str(), stdout);
    }
    std::fputs(formatSummary(passed, failed).c_str(), stdout);
    return failed == 0 ? 0 : 1;
}

Command checkCommand() {
    return {
        "check", "check a stage against the solution from several camera views", [](CLI::App& cmd) {
            auto stage = std::make_shared<StageOptions>();
            auto check = std::make_shared<CheckOptions>();
            stage->size = "160x120";
            CLI::Option* lab = addStageOptions(cmd, *stage, false);
            addSceneTransformOptions(cmd, *stage);
            cmd.add_option("--against", check->againstDir,
                           "compare with DIR/<view>.png instead of the solution rendered now");
            cmd.add_option("--save", check->saveDir, "write the checked images to DIR/<view>.png");
            cmd.add_option("--timeout", check->timeoutSeconds,
                           "stop the check after this many seconds (default 600)")
                ->check(CLI::PositiveNumber);
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
