#include "application.h"

#include "error.h"
#include "gl.h"
#include "gl_loader.h"

#include <cstdio>
#include <cstdlib>

namespace raylab {

namespace {
// Without a display SDL falls back to its invisible "offscreen" driver and the
// loop would run unseen forever; refuse unless a driver was asked for.
bool canShowAWindow() {
    for (const char* var : {"DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"}) {
        const char* value = std::getenv(var);
        if (value && *value) return true;
    }
    return false;
}
}  // namespace

Application::Application(const Options& options) : options_(options) {
    if (!canShowAWindow())
        throw Error("cannot open a window: no display (DISPLAY and WAYLAND_DISPLAY are unset); use "
                    "`raylab render` or "
                    "`raylab demo`, or run under xvfb-run");
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
        throw Error(std::string("cannot open a window (") + SDL_GetError() +
                    "); without a display use `raylab render` or `raylab demo`");
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
    window_ = SDL_CreateWindow(options.title.c_str(), SDL_WINDOWPOS_CENTERED,
                               SDL_WINDOWPOS_CENTERED, options.width, options.height,
                               SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (!window_) {
        std::string why = SDL_GetError();
        SDL_Quit();
        throw Error("cannot create a window: " + why);
    }
    context_ = SDL_GL_CreateContext(window_);
    if (!context_) {
        std::string why = SDL_GetError();
        SDL_DestroyWindow(window_);
        SDL_Quit();
        throw Error("cannot create an OpenGL 3.3 core context: " + why);
    }
    loadGlWithGlew();
    requireGl33();
    setVsync(options.vsync);
}

Application::~Application() {
    if (context_) SDL_GL_DeleteContext(context_);
    if (window_) SDL_DestroyWindow(window_);
    SDL_Quit();
}

void Application::setVsync(bool on) {
    const bool refused = SDL_GL_SetSwapInterval(on ? 1 : 0) != 0 && on;
    if (refused && !vsyncRefused_) std::fprintf(stderr, "raylab: vsync is not available here\n");
    vsyncRefused_ = refused;
    vsync_ = on && !refused;
}

int Application::run() {
    init();
    Uint64 last = SDL_GetPerformanceCounter();
    Uint64 fpsStart = last;
    int fpsFrames = 0;
    while (!quit_) {
        SDL_Event event;
        while (SDL_PollEvent(&event)) {
            if (event.type == SDL_QUIT) quit_ = true;
            onEvent(event);
        }
        Uint64 now = SDL_GetPerformanceCounter();
        float dt = float(double(now - last) / double(SDL_GetPerformanceFrequency()));
        last = now;
        update(dt);
        render();
        SDL_GL_SwapWindow(window_);

        ++fpsFrames;
        double elapsed = double(now - fpsStart) / double(SDL_GetPerformanceFrequency());
        if (elapsed >= 0.5) {
            char title[512];
            std::snprintf(title, sizeof title, "%s | %.0f FPS%s%s%s", options_.title.c_str(),
                          fpsFrames / elapsed, vsync_ ? " (vsync)" : "",
                          status_.empty() ? "" : " | ", status_.c_str());
            SDL_SetWindowTitle(window_, title);
            fpsStart = now;
            fpsFrames = 0;
        }
    }
    return 0;
}

}  // namespace raylab
