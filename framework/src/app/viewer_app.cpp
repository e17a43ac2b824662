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
}  // namespace

ViewerApp::ViewerApp(StageSetup setup, Automation automation, bool vsync)
    : Application(Options{"RayLab " + setup.stage->id + " (" + setup.sources.label + ")",
                          setup.size.width, setup.size.height, vsync}),
      setup_(std::move(setup)), automation_(std::move(automation)) {}

void ViewerApp::init() {
    int w = 0, h = 0;
    drawableSize(&w, &h);
    renderer_ = makeTrackRenderer(setup_, w, h);
    renderer_->completeSettings(setup_.settings);
    reportOpenTodos(renderer_->openTodos());
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
    if (forward != 0.0f || right != 0.0f) setup_.camera.move(forward * step, right * step);

    sinceReloadCheck_ += dt;
    if (sinceReloadCheck_ >= kReloadPollSeconds) {
        sinceReloadCheck_ = 0.0f;
        if (watcher_.changed()) reloadShaders();
    }
}

void ViewerApp::render() {
    int w = 0, h = 0;
    drawableSize(&w, &h);
    if (w != renderer_->width() || h != renderer_->height()) renderer_->resize(w, h);
    renderer_->render(setup_.camera, time_, setup_.settings);
    renderer_->blitToScreen(w, h);
    if (overlay_ && showOverlay_) drawOverlay();
    ++frames_;
    if (automation_.exitAfterFrames > 0 && frames_ >= automation_.exitAfterFrames) {
        if (!automation_.screenshotFile.empty()) screenshot(automation_.screenshotFile);
        quit();
    }
}

void ViewerApp::screenshot(const std::string& file) {
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
        if (looking_)
            setup_.camera.turn(float(event.motion.xrel) * kMouseDegPerPixel,
                               -float(event.motion.yrel) * kMouseDegPerPixel);
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
    std::vector<std::pair<std::string, std::string>> rows = {{"frame", frame}};
    for (auto& row : settingsRows(s, setup_.stage->track)) rows.push_back(std::move(row));
    rows.insert(rows.end(), {{"[V] vsync", vsyncState()},
                             {"[P] animation", paused_ ? "paused" : "running"},
                             {"[H] hide this panel", ""}});
    overlay_->draw("RayLab " + setup_.stage->id + " - " + displayPath(setup_.sceneFile), rows);
}

}  // namespace raylab
