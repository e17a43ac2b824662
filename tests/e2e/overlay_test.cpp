// The window's overlay (Dear ImGui) draws its panel into a real X window's
// default framebuffer (Xvfb, Mesa llvmpipe through GLX), leaves the GL state
// the framework relies on as it found it, and shows the rows it is given.
#include "error.h"
#include "gl.h"
#include "gl_loader.h"
#include "overlay.h"
#include "test_support.h"

#include <SDL.h>
#include <gtest/gtest.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <fcntl.h>
#include <optional>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace raylab::test;

namespace {

using Rows = std::vector<std::pair<std::string, std::string>>;

constexpr int kWidth = 320, kHeight = 240;
// The clear colour: exact in 8 bits (0.2, 0.4, 0.8 times 255).
constexpr std::array<std::uint8_t, 3> kClear = {51, 102, 204};

// An Xvfb server of its own, on a display number that the server picks
// (-displayfd), so parallel tests never race for one. Stopped on destruction.
class XvfbServer {
public:
    XvfbServer() {
        int fds[2];
        if (pipe(fds) != 0) {
            error_ = "pipe failed";
            return;
        }
        pid_ = fork();
        if (pid_ == 0) {
            close(fds[0]);
            int devnull = open("/dev/null", O_RDWR);
            if (devnull >= 0) {
                dup2(devnull, 0);
                dup2(devnull, 1);
                dup2(devnull, 2);
            }
            const std::string fd = std::to_string(fds[1]);
            // 24-bit screen: an 8-bit one has no OpenGL visual.
            execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "640x480x24",
                   "-nolisten", "tcp", static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        if (pid_ < 0) {
            close(fds[0]);
            error_ = "fork failed";
            return;
        }
        // Xvfb writes its display number and a newline once it accepts clients.
        std::string number;
        pollfd p{fds[0], POLLIN, 0};
        for (;;) {
            int ready = poll(&p, 1, 20000);
            if (ready < 0 && errno == EINTR) continue;
            char c = 0;
            if (ready <= 0 || read(fds[0], &c, 1) != 1 || c == '\n') break;
            number += c;
        }
        close(fds[0]);
        if (number.empty()) error_ = "Xvfb did not start (no display number within 20 s)";
        else display_ = ":" + number;
    }
    ~XvfbServer() {
        if (pid_ <= 0) return;
        kill(pid_, SIGTERM);
        int status = 0;
        waitpid(pid_, &status, 0);
    }
    XvfbServer(const XvfbServer&) = delete;
    XvfbServer& operator=(const XvfbServer&) = delete;

    bool ok() const { return !display_.empty(); }
    const std::string& display() const { return display_; }
    const std::string& error() const { return error_; }

private:
    pid_t pid_ = -1;
    std::string display_, error_;
};

// Sets an environment variable for the test's lifetime.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (old_) setenv(name_, old_->c_str(), 1);
        else unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

// An SDL window with a current OpenGL 3.3 core context, as Application makes it.
struct GlWindow {
    SDL_Window* window = nullptr;
    SDL_GLContext context = nullptr;
    std::string error;

    GlWindow() {
        if (SDL_Init(SDL_INIT_VIDEO) != 0) {
            error = std::string("SDL_Init: ") + SDL_GetError();
            return;
        }
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
        SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
        SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
        window = SDL_CreateWindow("overlay test", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                  kWidth, kHeight, SDL_WINDOW_OPENGL | SDL_WINDOW_ALLOW_HIGHDPI);
        if (!window) {
            error = std::string("SDL_CreateWindow: ") + SDL_GetError();
            return;
        }
        context = SDL_GL_CreateContext(window);
        if (!context) error = std::string("SDL_GL_CreateContext: ") + SDL_GetError();
    }
    ~GlWindow() {
        if (context) SDL_GL_DeleteContext(context);
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
    }
    GlWindow(const GlWindow&) = delete;
    GlWindow& operator=(const GlWindow&) = delete;
};

struct Pixels {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // bottom row first, as glReadPixels gives it
    // (x, y) with y counted from the top, like window coordinates.
    std::array<std::uint8_t, 3> at(int x, int yFromTop) const {
        const std::size_t i =
            (std::size_t(height - 1 - yFromTop) * std::size_t(width) + std::size_t(x)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2]};
    }
    // Pixels in [x0, x1) x [y0, y1) (from the top) whose colour is not the clear colour.
    int notClear(int x0, int y0, int x1, int y1) const {
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) n += at(x, y) != kClear;
        return n;
    }
    // Pixels in the same region that differ between two frames.
    int differing(const Pixels& other, int x0, int y0, int x1, int y1) const {
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) n += at(x, y) != other.at(x, y);
        return n;
    }
};

GLint getInt(GLenum what) {
    GLint value = 0;
    glGetIntegerv(what, &value);
    return value;
}

// Clears the default framebuffer, draws the overlay, and reads the back buffer.
Pixels drawFrame(raylab::Overlay& overlay, const std::string& title, const Rows& rows) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.2f, 0.4f, 0.8f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    overlay.draw(title, rows);
    glFinish();
    Pixels p;
    p.width = kWidth;
    p.height = kHeight;
    p.rgba.resize(std::size_t(kWidth) * kHeight * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, p.rgba.data());
    return p;
}

}  // namespace

TEST(Overlay, DrawsItsPanelOverARealWindow) {
    // No skip: without Xvfb this test cannot check the overlay at all.
    ASSERT_EQ(runCommand("command -v Xvfb").exitCode, 0)
        << "Xvfb is not installed: the overlay test needs a real X window (install.sh --test "
           "installs the "
           "xvfb package)";
    XvfbServer xvfb;
    ASSERT_TRUE(xvfb.ok()) << xvfb.error();
    ScopedEnv display("DISPLAY", xvfb.display());
    ScopedEnv driver("SDL_VIDEODRIVER", "x11");

    GlWindow gl;
    ASSERT_TRUE(gl.error.empty()) << gl.error << " (display " << xvfb.display() << ")";
    int drawableW = 0, drawableH = 0;
    SDL_GL_GetDrawableSize(gl.window, &drawableW, &drawableH);
    ASSERT_EQ(drawableW, kWidth);
    ASSERT_EQ(drawableH, kHeight);
    raylab::loadGlWithGlew();
    raylab::requireGl33();

    const std::filesystem::path ini = std::filesystem::current_path() / "imgui.ini";
    const bool iniBefore = std::filesystem::exists(ini);
    {
        raylab::Overlay overlay(gl.window, gl.context);

        // GL state the framework sets before its own draws, to be found unchanged afterwards.
        GLuint vao = 0;
        glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
        glUseProgram(0);
        glDisable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
        glActiveTexture(GL_TEXTURE0);

        const Rows rowsA = {{"stage", "01-raycast"}, {"camera", "0.0, 1.5, 6.0"}, {"frame", "1"}};
        const Rows rowsB = {
            {"stage", "04-recursion"}, {"camera", "9.9, -8.8, 7.7"}, {"frame", "12345"}};
        Pixels a = drawFrame(overlay, "RayLab overlay test", rowsA);

        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        EXPECT_EQ(getInt(GL_VERTEX_ARRAY_BINDING), GLint(vao));
        EXPECT_EQ(getInt(GL_CURRENT_PROGRAM), 0);
        EXPECT_EQ(getInt(GL_DRAW_FRAMEBUFFER_BINDING), 0);
        EXPECT_EQ(getInt(GL_TEXTURE_BINDING_2D), 0);
        EXPECT_EQ(getInt(GL_ACTIVE_TEXTURE), GL_TEXTURE0);
        EXPECT_FALSE(glIsEnabled(GL_BLEND));
        EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
        GLint viewport[4] = {};
        glGetIntegerv(GL_VIEWPORT, viewport);
        EXPECT_EQ(viewport[2], kWidth);
        EXPECT_EQ(viewport[3], kHeight);

        // The panel (top-left, 10 px in) covers its corner region - from the
        // very first call - while the far corner keeps the clear colour.
        EXPECT_EQ(a.notClear(12, 12, 60, 24), 48 * 12) << "no panel in the top-left corner";
        EXPECT_EQ(a.notClear(kWidth - 40, kHeight - 40, kWidth, kHeight), 0)
            << "the overlay drew over the far corner";
        EXPECT_EQ(a.notClear(0, 0, kWidth, 8), 0) << "the panel should start 10 px from the top";

        // Same rows, same pixels; other rows, other pixels (the text is drawn).
        Pixels a2 = drawFrame(overlay, "RayLab overlay test", rowsA);
        EXPECT_EQ(a2.differing(a, 0, 0, kWidth, kHeight), 0)
            << "the same rows drew different pixels";
        drawFrame(overlay, "RayLab overlay test",
                  rowsB);  // an auto-sized panel follows its text one frame late
        Pixels b = drawFrame(overlay, "RayLab overlay test", rowsB);
        EXPECT_GT(b.differing(a, 0, 0, kWidth / 2, kHeight / 2), 50)
            << "changing the rows did not change the panel";
        EXPECT_EQ(b.notClear(kWidth - 40, kHeight - 40, kWidth, kHeight), 0);
        Pixels c = drawFrame(overlay, "Another title", rowsA);
        EXPECT_GT(c.differing(a, 0, 0, kWidth / 2, kHeight / 2), 20)
            << "changing the title did not change the panel";

        // Events pass through without effect on the picture (display only).
        SDL_Event click{};
        click.type = SDL_MOUSEBUTTONDOWN;
        click.button.button = SDL_BUTTON_LEFT;
        click.button.x = 20;
        click.button.y = 20;
        overlay.processEvent(click);
        drawFrame(overlay, "RayLab overlay test", rowsA);  // back to the size of rowsA's panel
        Pixels afterClick = drawFrame(overlay, "RayLab overlay test", rowsA);
        EXPECT_EQ(afterClick.differing(a, 0, 0, kWidth, kHeight), 0)
            << "an event changed the panel";

        glBindVertexArray(0);
        glDeleteVertexArrays(1, &vao);
    }
    EXPECT_EQ(std::filesystem::exists(ini), iniBefore) << "the overlay wrote imgui.ini";
}

TEST(Overlay, RefusesAMissingWindowOrContext) {
    EXPECT_THROW(raylab::Overlay(nullptr, nullptr), raylab::Error);
}
