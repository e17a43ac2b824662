#pragma once
// What the framework asks of a track's renderer. Each course track (the ray
// tracer; later the real-time fur track) draws its stages its own way, and a
// new track adds a renderer (and a line in app/tracks.cpp) instead of
// branching inside an existing one. Today the window (`raylab run`, the
// demo's window) draws through this interface; headless rendering, the
// checks, grading and the bench still make the ray tracer's StageRenderer
// directly (see framework/README.md, "Add a track").
#include "camera.h"
#include "image.h"
#include "pixel_format.h"
#include "render_settings.h"
#include "shader_source.h"

#include <filesystem>
#include <vector>

namespace raylab {

class TrackRenderer {
public:
    virtual ~TrackRenderer() = default;

    // Draws one frame into the off-screen target.
    virtual void render(const Camera& camera, float timeSeconds,
                        const RenderSettings& settings) = 0;
    // The last frame, as a picture, and its size.
    virtual Image read() const = 0;
    virtual int width() const = 0;
    virtual int height() const = 0;
    // Copies the last frame to the window's screen, scaled to its size.
    virtual void blitToScreen(int screenWidth, int screenHeight) const = 0;
    // A new render target of another size (the window was resized).
    virtual void resize(int width, int height, PixelFormat format = PixelFormat::Rgba8) = 0;

    // Rebuilds the program from the files on disk. On failure the previous
    // program stays in use and the error (Error or ShaderError) is thrown.
    virtual void rebuild() = 0;
    // The files the current program was built from (hot reload watches them).
    virtual const std::vector<std::filesystem::path>& sourceFiles() const = 0;
    // Stubs of the lab that are still unsolved (empty for the solution).
    virtual const std::vector<OpenTodo>& openTodos() const = 0;
};

}  // namespace raylab
