#include "viewer_app.h"

#include "error.h"
#include "paths.h"
#include "settings_keys.h"
#include "shader_program.h"
#include "track_registry.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace raylab {

namespace {
constexpr float kMoveSpeed = 3.0f;   // units per second
constexpr float kSlowFactor = 0.2f;  // while Left Shift is held
constexpr float kMouseDegPerPixel = 0.2f;
constexpr float kReloadPollSeconds = 0.3f;
constexpr float kWalkStep = 0.02f;  // units per frame of a scripted walk (--walk)

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}
}  // namespace

ViewerApp::ViewerApp(StageSetup setup, Automation automation, bool vsync, bool reduceWhileMoving)
    : Application(Options{"RayLab " + setup.stage->id + " (" + setup.sources.label + ")",
                          setup.size.width, setup.size.height, vsync}),
      setup_(std::move(setup)), automation_(std::move(automation)), motion_(reduceWhileMoving) {}

void ViewerApp::init() {
    int w = 0, h = 0;
    drawableSize(&w, &h);
    renderer_ = makeTrackRenderer(setup_, w, h);
    renderer_->completeSettings(setup_.settings);
    reportOpenTodos(renderer_->openTodos());
    if (!renderer_->sceneNote().empty())
        std::printf("raylab: %s\n", renderer_->sceneNote().c_str());
    watcher_.watch(renderer_->sourceFiles());
    time_ = setup_.time;
    try {
        overlay_ = std::make_unique<Overlay>(SDL_GL_GetCurrentWindow(), SDL_GL_GetCurrentContext());
    } catch (const Error& e) {
        std::fprintf(stderr, "raylab: no overlay (%s)\n", e.what());  // the window works without it
    }
}

void ViewerApp::reloadShaders() {
    try {
        renderer_->rebuild();
        setStatus("");
        std::fprintf(stderr, "raylab: shaders reloaded\n");
        reportOpenTodos(renderer_->openTodos());
    } catch (const ShaderError& e) {
        // Keep the last good program running; show where the error is.
        std::fprintf(stderr, "%s", e.log().c_str());
        setStatus(std::string("shader error: ") + e.what());
    } catch (const Error& e) {
        std::fprintf(stderr, "raylab: error: %s\n", e.what());
        setStatus(std::string("error: ") + e.what());
    }
    watcher_.watch(renderer_->sourceFiles());
}

void ViewerApp::update(float dt) {
    frameMs_ = frameMs_ == 0.0f ? dt * 1000.0f : 0.9f * frameMs_ + 0.1f * dt * 1000.0f;
    // Scripted runs (--frames) keep the time fixed so their frames are reproducible.
    if (!paused_ && automation_.exitAfterFrames == 0) time_ += dt;
    const Uint8* keys = SDL_GetKeyboardState(nullptr);
    float step = kMoveSpeed * dt * (keys[SDL_SCANCODE_LSHIFT] ? kSlowFactor : 1.0f);
    float forward = float(keys[SDL_SCANCODE_W]) - float(keys[SDL_SCANCODE_S]);
    float right = float(keys[SDL_SCANCODE_D]) - float(keys[SDL_SCANCODE_A]);
    if (forward != 0.0f || right != 0.0f) {
        setup_.camera.move(forward * step, right * step);
        cameraMoved_ = true;
    }
    if (frames_ < automation_.walkFrames) {
        setup_.camera.move(kWalkStep, 0.0f);
        cameraMoved_ = true;
    }
    // dt is the previous frame's time; a scripted run keeps it for its
    // summary (the first frame compiles the shaders and is left out).
    const int drawnAt = motion_.divisor();
    if (automation_.exitAfterFrames > 0 && frames_ > 1)
        (drawnAt > 1 ? reducedMs_ : fullMs_).push_back(dt * 1000.0);
    motion_.update(dt * 1000.0, cameraMoved_);
    cameraMoved_ = false;

    sinceReloadCheck_ += dt;
    if (sinceReloadCheck_ >= kReloadPollSeconds) {
        sinceReloadCheck_ = 0.0f;
        if (watcher_.changed()) reloadShaders();
    }
}

// Draws the frame at 1/DIVISOR of the window's width and height.
void ViewerApp::renderAtDivisor(int divisor) {
    int w = 0, h = 0;
    drawableSize(&w, &h);
    const int rw = reducedSize(w, divisor), rh = reducedSize(h, divisor);
    if (rw != renderer_->width() || rh != renderer_->height()) renderer_->resize(rw, rh);
    renderer_->render(setup_.camera, time_, setup_.settings);
}

void ViewerApp::render() {
    int w = 0, h = 0;
    drawableSize(&w, &h);
    renderAtDivisor(motion_.divisor());
    renderer_->blitToScreen(w, h);
    if (overlay_ && showOverlay_) drawOverlay();
    ++frames_;
    if (automation_.exitAfterFrames > 0 && frames_ >= automation_.exitAfterFrames) {
        if (!automation_.screenshotFile.empty()) screenshot(automation_.screenshotFile);
        printFrameSummary();
        quit();
    }
}

// One line for scripts: the median frame time at full and reduced resolution.
void ViewerApp::printFrameSummary() const {
    std::printf("raylab: %d frames; full resolution (%dx%d): %zu frames, median %.1f ms; "
                "reduced while moving: %zu frames, median %.1f ms\n",
                frames_, setup_.size.width, setup_.size.height, fullMs_.size(), median(fullMs_),
                reducedMs_.size(), median(reducedMs_));
    std::fflush(stdout);
}

// A screenshot is always of the full resolution, also while moving.
void ViewerApp::screenshot(const std::string& file) {
    int w = 0, h = 0;
    drawableSize(&w, &h);
    if (w != renderer_->width() || h != renderer_->height()) renderAtDivisor(1);
    writePngAtomic(renderer_->read(), file);
    std::printf("raylab: screenshot written to %s\n", file.c_str());
    std::fflush(stdout);
}

void ViewerApp::onEvent(const SDL_Event& event) {
    if (overlay_) overlay_->processEvent(event);
    switch (event.type) {
    case SDL_MOUSEBUTTONDOWN:
        if (event.button.button == SDL_BUTTON_LEFT) looking_ = true;
        break;
    case SDL_MOUSEBUTTONUP:
        if (event.button.button == SDL_BUTTON_LEFT) looking_ = false;
        break;
    case SDL_MOUSEMOTION:
        if (looking_) {
            setup_.camera.turn(float(event.motion.xrel) * kMouseDegPerPixel,
                               -float(event.motion.yrel) * kMouseDegPerPixel);
            cameraMoved_ = true;
        }
        break;
    case SDL_KEYDOWN:
        if (!event.key.repeat) onKey(event.key.keysym.sym);
        break;
    default: break;
    }
}

void ViewerApp::onKey(SDL_Keycode key) {
    if (auto echo = applySettingsKey(setup_.settings, key, setup_.stage->track)) {
        std::printf("%s\n", echo->c_str());
        std::fflush(stdout);
        return;
    }
    switch (key) {
    case SDLK_ESCAPE: quit(); break;
    case SDLK_v:
        setVsync(!vsync());  // from "unavailable": asks again
        std::printf("vsync %s\n", vsyncState());
        break;
    case SDLK_r:
        motion_.setEnabled(!motion_.enabled());
        std::printf("while moving: %s\n",
                    motion_.enabled() ? "reduced resolution" : "full resolution");
        break;
    case SDLK_p:
        paused_ = !paused_;
        std::printf("animation %s\n", paused_ ? "paused" : "running");
        break;
    case SDLK_h:
        showOverlay_ = !showOverlay_;
        std::printf("overlay %s\n", showOverlay_ ? "shown" : "hidden");
        break;
    case SDLK_F12: {
        char name[64];
        std::time_t now = std::time(nullptr);
        std::strftime(name, sizeof name, "raylab-%Y%m%d-%H%M%S.png", std::localtime(&now));
        try {
            screenshot(name);
        } catch (const Error& e) { std::fprintf(stderr, "raylab: error: %s\n", e.what()); }
        break;
    }
    default: break;
    }
    std::fflush(stdout);
}

// The state of every switch, and the key that changes it.
void ViewerApp::drawOverlay() {
    const RenderSettings& s = setup_.settings;
    char frame[64];
    std::snprintf(frame, sizeof frame, "%.1f ms (%.0f FPS)", frameMs_,
                  frameMs_ > 0.0f ? 1000.0f / frameMs_ : 0.0f);
    char drawn[64];
    std::snprintf(drawn, sizeof drawn, "%dx%d%s", renderer_->width(), renderer_->height(),
                  motion_.divisor() > 1 ? " (moving)" : "");
    std::vector<std::pair<std::string, std::string>> rows = {{"frame", frame}, {"drawn at", drawn}};
    for (auto& row : settingsRows(s, setup_.stage->track)) rows.push_back(std::move(row));
    rows.insert(rows.end(),
                {{"[R] while moving", motion_.enabled() ? "fewer pixels" : "full resolution"},
                 {"[V] vsync", vsyncState()},
                 {"[P] animation", paused_ ? "paused" : "running"},
                 {"[H] hide this panel", ""}});
    overlay_->draw("RayLab " + setup_.stage->id + " - " + displayPath(setup_.sceneFile), rows);
}

}  // namespace raylab
