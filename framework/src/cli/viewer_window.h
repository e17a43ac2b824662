#pragma once
// The interactive window of `raylab run` and `raylab demo`, behind one call so
// that a headless build (-DRAYLAB_WINDOW=OFF: no app module, no SDL2 window,
// no Dear ImGui) still builds every command: viewer_window.cpp opens the
// window, viewer_window_none.cpp says it is not built in.
#include "stage_setup.h"

#include <string>

namespace raylab {

struct ViewerWindowOptions {
    int exitAfterFrames = 0;  // 0: run until closed
    std::string screenshot;   // with exitAfterFrames: the last frame to this PNG
    bool vsync = true;
    bool reduceWhileMoving = true;  // fewer pixels while the camera moves (key R)
    int walkFrames = 0;             // with exitAfterFrames: walk forward during the first N
};

// Whether this raylab was built with the window (RAYLAB_WINDOW).
bool windowBuiltIn();

// Opens SETUP's stage in a window and returns the exit code when it closes.
// In a headless build: Error naming the build option.
int openViewerWindow(StageSetup setup, const ViewerWindowOptions& options);

}  // namespace raylab
