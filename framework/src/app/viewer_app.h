#pragma once
// The interactive window for one stage: FPS-style camera, shader hot reload,
// screenshots. Keys: W/A/S/D move, Left Shift slows down, mouse look while the
// left button is held, 1 shadows, G glow, N normal maps, Right/Left max
// depth, Up/Down colour mode, R fewer pixels while moving, V vsync, P pause
// time, H hide the overlay, F12 screenshot, Esc quit. Every toggle is echoed on the terminal and
// the current state is shown in an overlay.
#include "application.h"
#include "file_watcher.h"
#include "motion_resolution.h"
#include "overlay.h"
#include "stage_setup.h"
#include "track_renderer.h"

#include <memory>
#include <string>
#include <vector>

namespace raylab {

class ViewerApp : public Application {
public:
    struct Automation {
        int exitAfterFrames = 0;     // 0: run until closed
        std::string screenshotFile;  // written at exit when set
        int walkFrames = 0;          // the camera walks forward during the first N frames
    };

    ViewerApp(StageSetup setup, Automation automation, bool vsync, bool reduceWhileMoving);

protected:
    void init() override;
    void update(float dtSeconds) override;
    void render() override;
    void onEvent(const SDL_Event& event) override;

private:
    void reloadShaders();
    void screenshot(const std::string& file);
    void onKey(SDL_Keycode key);
    void drawOverlay();
    void renderAtDivisor(int divisor);
    void printFrameSummary() const;

    StageSetup setup_;
    Automation automation_;
    std::unique_ptr<TrackRenderer> renderer_;
    std::unique_ptr<Overlay> overlay_;
    bool showOverlay_ = true;
    float frameMs_ = 0.0f;  // smoothed frame time for the overlay
    FileWatcher watcher_;
    float time_ = 0.0f;
    float sinceReloadCheck_ = 0.0f;
    bool paused_ = false;
    bool looking_ = false;
    int frames_ = 0;
    MotionResolution motion_;
    bool cameraMoved_ = false;  // since the previous frame
    // Frame times of a scripted run (--frames), for its summary line.
    std::vector<double> fullMs_, reducedMs_;
};

}  // namespace raylab
