#pragma once
// The interactive window for one stage: FPS-style camera, shader hot reload,
// screenshots. Keys: W/A/S/D move, Left Shift slows down, mouse look while the
// left button is held, 1 shadows, Right/Left max depth, V vsync, P pause time,
// F12 screenshot, Esc quit.
#include "application.h"
#include "file_watcher.h"
#include "stage_renderer.h"
#include "stage_setup.h"

#include <memory>
#include <string>

namespace raylab {

class ViewerApp : public Application {
public:
    struct Automation {
        int exitAfterFrames = 0;     // 0: run until closed
        std::string screenshotFile;  // written at exit when set
    };

    ViewerApp(StageSetup setup, Automation automation, bool vsync);

protected:
    void init() override;
    void update(float dtSeconds) override;
    void render() override;
    void onEvent(const SDL_Event& event) override;

private:
    void reloadShaders();
    void screenshot(const std::string& file);

    StageSetup setup_;
    Automation automation_;
    std::unique_ptr<StageRenderer> renderer_;
    FileWatcher watcher_;
    float time_ = 0.0f;
    float sinceReloadCheck_ = 0.0f;
    bool paused_ = false;
    bool looking_ = false;
    int frames_ = 0;
};

} // namespace raylab
