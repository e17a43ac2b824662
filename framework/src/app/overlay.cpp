#include "overlay.h"

#include "error.h"

// Debian's libimgui-dev ships the core and its backends compiled into
// libimgui.a; the headers live in /usr/include/imgui (pkg-config imgui).
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <algorithm>

namespace raylab {

namespace {

constexpr float kMargin = 10.0f;  // from the window's top-left corner, in window pixels
constexpr float kBgAlpha = 0.6f;  // panel background opacity
const ImVec4 kLabelColour(0.70f, 0.70f, 0.70f, 1.0f);

// A display-only window: no title bar, no input, never focused, never saved.
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoNav |
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing |
    ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_AlwaysAutoResize;

// Makes the overlay's ImGui context current for one call and puts the previous one back.
class UseContext {
public:
    explicit UseContext(ImGuiContext* context) : previous_(ImGui::GetCurrentContext()) {
        ImGui::SetCurrentContext(context);
    }
    ~UseContext() { ImGui::SetCurrentContext(previous_); }
    UseContext(const UseContext&) = delete;
    UseContext& operator=(const UseContext&) = delete;

private:
    ImGuiContext* previous_;
};

}  // namespace

Overlay::Overlay(SDL_Window* window, SDL_GLContext context) {
    if (!window || !context)
        throw Error("cannot start the overlay: no window or no OpenGL context");
    if (SDL_GL_GetCurrentContext() != context)
        throw Error("cannot start the overlay: its OpenGL context is not current");
    if (!IMGUI_CHECKVERSION())
        throw Error("cannot start the overlay: the Dear ImGui headers and library disagree");

    imgui_ = ImGui::CreateContext();
    UseContext use(imgui_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini on disk
    io.LogFilename = nullptr;
    // Leave the cursor and the mouse to the application; no keyboard/gamepad navigation.
    io.ConfigFlags |= ImGuiConfigFlags_NoMouseCursorChange | ImGuiConfigFlags_NoMouse;
    ImGui::StyleColorsDark();

    // The SDL backend turns on click-through focus for the whole application;
    // a display-only panel has no use for it, so the previous value is restored.
    const char* hint = SDL_GetHint(SDL_HINT_MOUSE_FOCUS_CLICKTHROUGH);
    const std::string clickThrough = hint ? hint : "0";
    sdlBackend_ = ImGui_ImplSDL2_InitForOpenGL(window, context);
    SDL_SetHint(SDL_HINT_MOUSE_FOCUS_CLICKTHROUGH, clickThrough.c_str());
    // The OpenGL3 backend loads its own entry points (gl3w: libGL.so.1 and
    // glXGetProcAddressARB, through glvnd), independently of GLEW.
    if (sdlBackend_) glBackend_ = ImGui_ImplOpenGL3_Init("#version 330 core");
    if (!sdlBackend_ || !glBackend_) {
        const std::string which = sdlBackend_ ? "OpenGL3" : "SDL2";
        if (sdlBackend_) ImGui_ImplSDL2_Shutdown();
        ImGui::DestroyContext(imgui_);
        imgui_ = nullptr;
        throw Error("cannot start the overlay: Dear ImGui's " + which +
                    " backend failed to initialise");
    }
}

Overlay::~Overlay() {
    if (!imgui_) return;
    {
        UseContext use(imgui_);
        if (glBackend_) ImGui_ImplOpenGL3_Shutdown();  // needs the GL context, still current here
        if (sdlBackend_) ImGui_ImplSDL2_Shutdown();
    }
    ImGui::DestroyContext(imgui_);
}

void Overlay::processEvent(const SDL_Event& e) {
    UseContext use(imgui_);
    ImGui_ImplSDL2_ProcessEvent(
        &e);  // only records input state; the event still goes to the application
}

void Overlay::buildPanel(const std::string& title,
                         const std::vector<std::pair<std::string, std::string>>& rows) {
    ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(kBgAlpha);
    if (ImGui::Begin("##raylab-overlay", nullptr, kPanelFlags)) {
        ImGui::TextUnformatted(title.c_str());
        if (!rows.empty()) ImGui::Separator();
        float labelWidth = 0.0f;
        for (const auto& row : rows)
            labelWidth = std::max(labelWidth, ImGui::CalcTextSize(row.first.c_str()).x);
        const float valueX =
            ImGui::GetCursorPosX() + labelWidth + 2.0f * ImGui::GetStyle().ItemSpacing.x;
        for (const auto& row : rows) {
            ImGui::PushStyleColor(ImGuiCol_Text, kLabelColour);
            ImGui::TextUnformatted(row.first.c_str());
            ImGui::PopStyleColor();
            ImGui::SameLine(valueX);
            ImGui::TextUnformatted(row.second.c_str());
        }
    }
    ImGui::End();
}

void Overlay::draw(const std::string& title,
                   const std::vector<std::pair<std::string, std::string>>& rows) {
    UseContext use(imgui_);
    // ImGui hides a new auto-sized window for one frame while it measures it;
    // the first call lays the panel out once without rendering, so that every
    // call, the first included, shows the panel.
    for (int pass = drawnBefore_ ? 1 : 0; pass < 2; ++pass) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplSDL2_NewFrame();  // window and drawable size, time step
        ImGuiIO& io = ImGui::GetIO();
        if (!(io.DeltaTime > 0.0f)) io.DeltaTime = 1e-6f;  // two calls within one clock tick
        ImGui::NewFrame();
        buildPanel(title, rows);
        if (pass == 0) {
            ImGui::EndFrame();
            continue;
        }
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    drawnBefore_ = true;
}

}  // namespace raylab
