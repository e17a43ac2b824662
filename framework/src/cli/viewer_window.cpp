// The window, through the app module (RAYLAB_WINDOW=ON).
#include "viewer_window.h"

#include "viewer_app.h"

namespace raylab {

bool windowBuiltIn() { return true; }

int openViewerWindow(StageSetup setup, const ViewerWindowOptions& options) {
    ViewerApp app(
        std::move(setup),
        ViewerApp::Automation{options.exitAfterFrames, options.screenshot, options.walkFrames},
        options.vsync, options.reduceWhileMoving);
    return app.run();
}

}  // namespace raylab
