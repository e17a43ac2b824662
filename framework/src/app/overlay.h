#pragma once
// A small on-screen panel drawn over the rendered frame (Dear ImGui, from
// Debian's libimgui-dev with its SDL2 and OpenGL3 backends). Display only: no
// widgets, it never takes focus or input and writes no imgui.ini. Students
// need not read this file.
//
// Use it in a window whose OpenGL 3.3 context is current (the interactive
// `raylab run` window): construct it after the context exists, pass every SDL
// event to processEvent(), call draw() once per frame after the frame is in
// the window's framebuffer and before the buffer swap, and destroy it before
// the context.
#include <SDL.h>

#include <string>
#include <utility>
#include <vector>

struct ImGuiContext;

namespace raylab {

class Overlay {
public:
    Overlay(SDL_Window* window,
            SDL_GLContext context);  // throws raylab::Error (framework/src/core/error.h) if ImGui
                                     // can't initialise
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    void processEvent(const SDL_Event& e);
    // Draws a semi-transparent panel in the top-left corner with a title line
    // and one row per (label, value) pair, into the currently bound framebuffer
    // (the window's default framebuffer). The panel is sized for the window's
    // current size, read from the window at each call (HiDPI-aware). GL state
    // that ImGui changes (program, VAO, textures, buffers, blend, scissor,
    // viewport, ...) is restored before it returns; the framebuffer binding is
    // left untouched.
    void draw(const std::string& title,
              const std::vector<std::pair<std::string, std::string>>& rows);

private:
    void buildPanel(const std::string& title,
                    const std::vector<std::pair<std::string, std::string>>& rows);

    ImGuiContext* imgui_ = nullptr;
    bool sdlBackend_ = false;
    bool glBackend_ = false;
    bool drawnBefore_ = false;
};

}  // namespace raylab
