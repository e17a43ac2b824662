// raylab: the command line of the course framework. See `raylab --help`.
#include "commands.h"
#include "error.h"
#include "shader_program.h"

#include <CLI/CLI.hpp>

#include <cstdio>

using namespace raylab;

namespace {

// Returns the --lab option: whether it was given is known only after parsing.
CLI::Option* addStageOptions(CLI::App* cmd, StageOptions& o, bool withCamera) {
    cmd->add_option("--stage", o.stage, "stage id or number, e.g. 01-raycast or 01 (see `raylab stages`)")->required();
    CLI::Option* lab = cmd->add_option("--lab", o.labDir, "use the lab in DIR (laid out like labs/); without DIR: labs/ (the default)")
                           ->expected(0, 1);
    cmd->add_flag("--solution", o.solution, "use the complete solution instead of a lab");
    cmd->add_option("--scene", o.scene, "scene file (default: the stage's scene under assets/scenes/)");
    cmd->add_option("--size", o.size, "image size WIDTHxHEIGHT")->capture_default_str();
    if (withCamera) {
        cmd->add_option("--camera", o.camera, "camera x,y,z,yaw,pitch in world units and degrees (default: the scene's)");
        cmd->add_option("--time", o.time, "animation time in seconds")->capture_default_str();
        cmd->add_flag("--no-shadows", o.noShadows, "start with shadows off (stage 03 on; key 1 in the window)");
        cmd->add_option("--depth", o.maxDepth, "rays per path, 1..8 (stage 04 on; arrow keys in the window)")->capture_default_str();
        cmd->add_flag("--no-glow", o.noGlow, "start without the sun's glow (stage 06 on; key G)");
        cmd->add_flag("--no-normal-maps", o.noNormalMaps, "start without normal maps (stage 07 on; key N)");
        cmd->add_option("--color-mode", o.colorMode, "colour mode RGB, BRB, BRR, RBB or GGR (stage 08; Up/Down)")->capture_default_str();
    }
    return lab;
}

} // namespace

int main(int argc, char** argv) {
    rememberProgramArguments(argc, argv);
    CLI::App app{"RayLab: build a real-time GPU ray tracer stage by stage, and grade it headlessly."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "help for every subcommand");

    app.add_subcommand("stages", "list the stages of the course");

    StageOptions runStage;
    RunOptions run;
    CLI::App* runCmd = app.add_subcommand("run", "open a stage in a window (W/A/S/D, mouse, V vsync, P pause, F12 screenshot)");
    CLI::Option* runLab = addStageOptions(runCmd, runStage, true);
    runCmd->add_flag("--no-vsync", run.noVsync, "start with vsync off");
    runCmd->add_option("--frames", run.exitAfterFrames, "quit after N frames (for scripts)")->check(CLI::Range(1, 1000000));
    runCmd->add_option("--screenshot", run.screenshot, "with --frames: write the last frame to this PNG");

    StageOptions renderStage;
    renderStage.size = "800x600";
    RenderOptions render;
    std::string renderBackend = "auto";
    CLI::App* renderCmd = app.add_subcommand("render", "render one frame (or a debug view of it) headless to a PNG or PFM file");
    CLI::Option* renderLab = addStageOptions(renderCmd, renderStage, true);
    renderCmd->add_option("--out", render.outFile, "output file: .png (a picture) or .pfm (raw floats)")->required();
    renderCmd->add_option("--backend", renderBackend, "headless backend: auto, egl or osmesa")->capture_default_str();
    renderCmd->add_option("--view", render.view, "color, depth, normal, id; with --reference also bounces, stack")->capture_default_str();
    renderCmd->add_flag("--reference", render.reference, "draw with the CPU reference tracer instead of the GPU");

    StageOptions raysStage;
    raysStage.size = "800x600";
    std::string raysOut, raysBackend = "auto";
    CLI::App* raysCmd = app.add_subcommand("rays", "write the primary rays the GPU computes for every pixel to a file");
    CLI::Option* raysLab = addStageOptions(raysCmd, raysStage, true);
    raysCmd->add_option("--out", raysOut, "output file (RLRAYS01: header, then origin and direction per pixel)")->required();
    raysCmd->add_option("--backend", raysBackend, "headless backend: auto, egl or osmesa")->capture_default_str();

    StageOptions traceStage;
    traceStage.size = "800x600";
    std::string tracePixel;
    CLI::App* traceCmd = app.add_subcommand("trace", "print one pixel's path bounce by bounce, from the CPU reference tracer (no GPU)");
    CLI::Option* traceLab = addStageOptions(traceCmd, traceStage, true);
    traceCmd->add_option("--pixel", tracePixel, "the pixel X,Y of the --size image (0,0 top left)")->required();

    GradeOptions grade;
    CLI::App* gradeCmd = app.add_subcommand("grade", "grade a whole class headlessly: one folder per student, each laid out like labs/");
    gradeCmd->add_option("--submissions", grade.submissions, "folder with one subfolder per student")->required();
    gradeCmd->add_option("--out", grade.outDir, "folder for report.html, summary.csv, junit.xml, <student>/results.json")->required();
    gradeCmd->add_option("--stages", grade.stages, "comma-separated stages to grade (default: all)");
    gradeCmd->add_option("--jobs", grade.jobs, "submissions graded at once")->capture_default_str();
    gradeCmd->add_option("--timeout", grade.timeoutSeconds, "seconds per stage of a submission")->capture_default_str();
    gradeCmd->add_option("--memory-mb", grade.memoryMb, "address-space limit per stage of a submission, MB (0: none)")->capture_default_str();
    gradeCmd->add_option("--seed", grade.seed, "seed of the extra camera views (keep it secret)")->capture_default_str();

    // The child-process halves of `grade` (hidden: an empty group).
    std::string itemStage, itemLab, itemStudent, itemOut;
    unsigned itemSeed = 0;
    CLI::App* gradeItemCmd = app.add_subcommand("grade-item", "")->group("");
    gradeItemCmd->add_option("--stage", itemStage)->required();
    gradeItemCmd->add_option("--lab", itemLab)->required();
    gradeItemCmd->add_option("--student", itemStudent)->required();
    gradeItemCmd->add_option("--out", itemOut)->required();
    gradeItemCmd->add_option("--seed", itemSeed);
    CLI::App* gradeRefCmd = app.add_subcommand("grade-reference", "")->group("");
    gradeRefCmd->add_option("--stage", itemStage)->required();
    gradeRefCmd->add_option("--out", itemOut)->required();
    gradeRefCmd->add_option("--seed", itemSeed);

    DemoOptions demo;
    std::string demoBackend = "auto";
    CLI::App* demoCmd = app.add_subcommand("demo", "run the full solution; without a display render it to an image and time it");
    demoCmd->add_option("--stage", demo.stage, "show this stage's solution (default: the highest finished stage)");
    demoCmd->add_option("--size", demo.size, "image size WIDTHxHEIGHT")->capture_default_str();
    demoCmd->add_option("--scene", demo.scene, "lite, pro or a scene file (default: the stage's scene)");
    demoCmd->add_option("--out", demo.outDir, "folder for the headless frames (default: a new raylab-demo-SCENE-TIME folder here)");
    demoCmd->add_option("--frames", demo.frames, "headless: frames of the fly-through to render and time (after one warm-up frame)")
        ->capture_default_str();
    demoCmd->add_flag("--no-shadows", demo.noShadows, "shadows off (key 1 in the window)");
    demoCmd->add_option("--depth", demo.maxDepth, "rays per path, 1..8 (arrow keys in the window)")->capture_default_str();
    demoCmd->add_flag("--headless", demo.headless, "render to a file even when a display is available");
    demoCmd->add_flag("--no-bvh", demo.noBvh, "stage 08: test every sphere for every ray instead of walking the BVH (used from 32 spheres on)");
    demoCmd->add_option("--backend", demoBackend, "headless backend: auto, egl or osmesa")->capture_default_str();

    BenchOptions bench;
    std::string benchBackend = "auto";
    CLI::App* benchCmd = app.add_subcommand("bench", "speed against error: frame and compile times and error against the reference tracer, "
                                                     "for the lite and pro scenes and a grid of settings (bench.csv, bench.md, bench.png)");
    benchCmd->add_option("--out", bench.outDir, "folder for bench.csv, bench.md and bench.png (made when missing)")->required();
    benchCmd->add_flag("--quick", bench.quick, "a small grid (lite, 160x120, one frame per setting): a smoke test, under a minute");
    benchCmd->add_option("--scenes", bench.scenes, "comma-separated: lite, pro or scene files (default: lite,pro)")->delimiter(',');
    benchCmd->add_option("--size", bench.size, "image size WIDTHxHEIGHT (default 800x600, quick 160x120)");
    benchCmd->add_option("--frames", bench.frames, "timed frames per setting (default 5, quick 1)");
    benchCmd->add_option("--backend", benchBackend, "headless backend: auto, egl or osmesa")->capture_default_str();

    StageOptions checkStage;
    checkStage.size = "160x120";
    CheckOptions check;
    std::string checkBackend = "auto";
    CLI::App* checkCmd = app.add_subcommand("check", "check a stage against the solution from several camera views");
    CLI::Option* checkLab = addStageOptions(checkCmd, checkStage, false);
    checkCmd->add_option("--against", check.againstDir, "compare with DIR/<view>.png instead of the solution rendered now");
    checkCmd->add_option("--save", check.saveDir, "write the checked images to DIR/<view>.png");
    checkCmd->add_option("--backend", checkBackend, "headless backend: auto, egl or osmesa")->capture_default_str();

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string help = "raylab --help";
        for (const CLI::App* sub : app.get_subcommands()) help = "raylab " + sub->get_name() + " --help";
        std::fprintf(stderr, "raylab: error: %s (see %s)\n", e.what(), help.c_str());
        return 2;
    }

    runStage.labGiven = runLab->count() > 0;
    renderStage.labGiven = renderLab->count() > 0;
    raysStage.labGiven = raysLab->count() > 0;
    checkStage.labGiven = checkLab->count() > 0;
    traceStage.labGiven = traceLab->count() > 0;

    try {
        if (app.got_subcommand("stages")) return cmdStages();
        if (runCmd->parsed()) return cmdRun(runStage, run);
        if (renderCmd->parsed()) {
            render.backend = parseBackend(renderBackend);
            return cmdRender(renderStage, render);
        }
        if (raysCmd->parsed()) return cmdRays(raysStage, raysOut, parseBackend(raysBackend));
        if (gradeCmd->parsed()) return cmdGrade(grade);
        if (gradeItemCmd->parsed()) return cmdGradeItem(itemStage, itemLab, itemStudent, itemOut, itemSeed);
        if (gradeRefCmd->parsed()) return cmdGradeReference(itemStage, itemOut, itemSeed);
        if (demoCmd->parsed()) {
            demo.backend = parseBackend(demoBackend);
            return cmdDemo(demo);
        }
        if (benchCmd->parsed()) {
            bench.backend = parseBackend(benchBackend);
            for (int i = 0; i < argc; ++i) bench.commandLine += (i ? " " : "") + std::string(i ? argv[i] : "raylab");
            return cmdBench(bench);
        }
        if (checkCmd->parsed()) {
            check.backend = parseBackend(checkBackend);
            return cmdCheck(checkStage, check);
        }
        if (traceCmd->parsed()) return cmdTrace(traceStage, tracePixel);
    } catch (const ShaderError& e) {
        std::fputs(e.log().c_str(), stderr);
        std::fprintf(stderr, "raylab: error: shader does not compile: %s\n", e.what());
        return 2;
    } catch (const Error& e) {
        std::fprintf(stderr, "raylab: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: internal error: %s\n", e.what());
        return 2;
    }
    return 2;
}
