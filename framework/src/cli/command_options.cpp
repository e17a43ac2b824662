#include "command_options.h"

#include <filesystem>
#include <system_error>

namespace raylab {

namespace {

// lite and pro are stage 08's scenes: a student repository holds them only
// once it releases stage 08 (release_assets.h), so its help offers them
// only then (asked for anyway, they are refused in one line: demoSceneFile).
// Looked up once, not for every command that has --scene.
const std::string& sceneOptionHelp() {
    static const std::string help = [] {
        const std::string where = "a scene file (default: the stage's scene under assets/scenes/)";
#ifdef RAYLAB_STUDENT_BUILD
        std::error_code ec;
        for (const char* name : {"lite", "pro"})
            if (!std::filesystem::is_regular_file(demoScenePath(name), ec)) return where;
#endif
        return "lite, pro or " + where;
    }();
    return help;
}

}  // namespace

CLI::Option* addStageOptions(CLI::App& cmd, StageOptions& o, bool withCamera) {
    cmd.add_option("--stage", o.stage,
                   "stage id or number, e.g. 01-raycast, 01 or f2 (see `raylab stages`)")
        ->required();
    CLI::Option* lab =
        cmd.add_option("--lab", o.labDir,
                       "use the lab in DIR (laid out like labs/); without DIR: labs/ (the default)")
            ->expected(0, 1);
#ifdef RAYLAB_STUDENT_BUILD
    // Not offered (a student repository holds no solution), but refused with
    // its reason rather than as an unknown option (resolveStageOptions).
    cmd.add_flag("--solution", o.solution)->group("");
#else
    cmd.add_flag("--solution", o.solution, "use the complete solution instead of a lab");
#endif
    cmd.add_option("--scene", o.scene, sceneOptionHelp());
    cmd.add_option("--size", o.size, "image size WIDTHxHEIGHT")->capture_default_str();
    if (withCamera) {
        cmd.add_option("--camera", o.camera,
                       "camera x,y,z,yaw,pitch in world units and degrees (default: the scene's)");
        addSceneTransformOptions(cmd, o);
        cmd.add_option("--time", o.time, "animation time in seconds")->capture_default_str();
        cmd.add_flag("--no-shadows", o.noShadows,
                     "start with shadows off (stage 03 on; key 1 in the window)");
        cmd.add_option("--depth", o.maxDepth,
                       "rays per path, 1..8 (stage 04 on; arrow keys in the window)")
            ->capture_default_str();
        cmd.add_flag("--no-glow", o.noGlow, "start without the sun's glow (stage 06 on; key G)");
        cmd.add_flag("--no-normal-maps", o.noNormalMaps,
                     "start without normal maps (stage 07 on; key N)");
        cmd.add_option("--color-mode", o.colorMode,
                       "colour mode RGB, BRB, BRR, RBB or GGR (stage 08; Up/Down)")
            ->capture_default_str();
        cmd.add_option(
            "--shells", o.shells,
            "fur track: shells drawn, the skin included (default: the scene's; keys [ ])");
        cmd.add_option("--fur-length", o.furLength,
                       "fur track: a factor on the scene's fur length (keys - =)")
            ->capture_default_str();
        cmd.add_flag("--no-fins", o.noFins, "fur track: start without fins (stage f3 on; key F)");
        cmd.add_option("--technique", o.technique,
                       "fur track: shells_and_fins or fur_shader (stage f4, whose pictures show "
                       "the fur shader by default; key T)");
    }
    return lab;
}

void addSceneTransformOptions(CLI::App& cmd, StageOptions& o) {
    cmd.add_option("--scene-scale", o.sceneScale,
                   "multiply every length of the scene by this factor (1e-6..1e8)");
    cmd.add_option("--scene-offset", o.sceneOffset,
                   "then move the whole scene by x,y,z (the camera with it)");
}

BackendOption::BackendOption(CLI::App& cmd) {
    cmd.add_option("--backend", name_, "headless backend: auto, egl or osmesa")
        ->capture_default_str();
}

}  // namespace raylab
