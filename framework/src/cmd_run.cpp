#include "commands.h"
#include "viewer_app.h"

#include <cstdlib>

namespace raylab {

bool displayAvailable() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

int cmdRun(const StageOptions& options, const RunOptions& run) {
    StageSetup setup = resolveStageOptions(options);
    ViewerApp app(std::move(setup), ViewerApp::Automation{run.exitAfterFrames, run.screenshot}, !run.noVsync);
    return app.run();
}

} // namespace raylab
