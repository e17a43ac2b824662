#include "command.h"
#include "command_options.h"
#include "commands.h"
#include "viewer_window.h"

#include <cstdlib>

namespace raylab {

bool displayAvailable() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

int cmdRun(const StageOptions& options, const RunOptions& run) {
    StageSetup setup = resolveStageOptions(options);
    return openViewerWindow(std::move(setup), {run.exitAfterFrames, run.screenshot, !run.noVsync,
                                               !run.fullResolution, run.walkFrames});
}

Command runCommand() {
    return {"run", "open a stage in a window (W/A/S/D, mouse, V vsync, P pause, F12 screenshot)",
            [](CLI::App& cmd) {
                auto stage = std::make_shared<StageOptions>();
                auto run = std::make_shared<RunOptions>();
                CLI::Option* lab = addStageOptions(cmd, *stage, true);
                cmd.add_flag("--no-vsync", run->noVsync, "start with vsync off");
                cmd.add_flag("--full-resolution", run->fullResolution,
                             "draw at full resolution also while the camera moves (key R)");
                CLI::Option* frames = cmd.add_option("--frames", run->exitAfterFrames,
                                                     "quit after N frames (for scripts)")
                                          ->check(CLI::Range(1, 1000000));
                cmd.add_option("--screenshot", run->screenshot,
                               "with --frames: write the last frame to this PNG");
                cmd.add_option("--walk", run->walkFrames,
                               "with --frames: walk forward during the first N frames "
                               "(measures the window while moving)")
                    ->check(CLI::Range(1, 1000000))
                    ->needs(frames);
                return std::function<int()>([=] {
                    stage->labGiven = lab->count() > 0;
                    return cmdRun(*stage, *run);
                });
            }};
}

}  // namespace raylab
