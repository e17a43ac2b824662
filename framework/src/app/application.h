#pragma once
// The application base of the course template: an SDL2 window with an OpenGL
// 3.3 core context and the classic loop
//     init(); while (!quit) { events; update(dt); render(); swap; }
// with vsync control and the frame rate in the title. Students need not read
// this file.
#include <SDL.h>

#include <string>

namespace raylab {

class Application {
public:
    struct Options {
        std::string title = "RayLab";
        int width = 800;
        int height = 600;
        bool vsync = true;
    };

    explicit Application(const Options& options);  // throws Error with no display
    virtual ~Application();
    Application(const Application&) = delete;
    Application& operator=(const Application&) = delete;

    int run();  // returns the process exit code

protected:
    virtual void init() = 0;
    virtual void update(float dtSeconds) = 0;
    virtual void render() = 0;  // draw; the base swaps buffers afterwards
    virtual void onEvent(const SDL_Event&) {}

    void quit() { quit_ = true; }
    bool vsync() const { return vsync_; }
    // Asks for vsync; where the driver refuses it (llvmpipe often does),
    // vsync() stays false and vsyncState() says "unavailable".
    void setVsync(bool on);
    const char* vsyncState() const { return vsync_ ? "on" : vsyncRefused_ ? "unavailable" : "off"; }
    // Text shown in the title after the frame rate (e.g. a shader error).
    void setStatus(const std::string& status) { status_ = status; }
    void drawableSize(int* width, int* height) const {
        SDL_GL_GetDrawableSize(window_, width, height);
    }

private:
    Options options_;
    SDL_Window* window_ = nullptr;
    SDL_GLContext context_ = nullptr;
    bool quit_ = false;
    bool vsync_ = true;
    bool vsyncRefused_ = false;  // the driver refused the last request for vsync
    std::string status_;
};

}  // namespace raylab
