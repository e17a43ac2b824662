// A headless build (RAYLAB_WINDOW=OFF): no window to open, and a message that
// says why and what works instead.
#include "viewer_window.h"

#include "error.h"

namespace raylab {

bool windowBuiltIn() { return false; }

int openViewerWindow(StageSetup, const ViewerWindowOptions&) {
    throw Error(
        "this raylab is a headless build (RAYLAB_WINDOW=OFF) and has no window: use render, "
        "check or demo --headless, or build with -DRAYLAB_WINDOW=ON");
}

}  // namespace raylab
