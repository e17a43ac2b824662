#pragma once
// What the framework asks of a track's renderer. Each course track (the ray
// tracer, the real-time fur) draws its stages its own way, and a new track
// adds a renderer (and a line in tracks/track_registry.cpp) instead of
// branching inside an existing one. The window, headless rendering, the
// checks and grading draw through this interface (framework/README.md,
// "Add a track").
#include "camera.h"
#include "image.h"
#include "pixel_format.h"
#include "render_settings.h"
#include "shader_source.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

// One view's result of a count check (stage.json "count_checks"): a number
// the GPU produced, compared with the same number worked out on the CPU.
struct CountResult {
    bool applies = true;  // false: this view does not draw what is counted (fins off)
    bool passed = false;
    std::string detail;  // "the geometry shader emitted 212 fins; 212 edges are silhouettes"
    // A build without the count's reference (RAYLAB_REFERENCES_AS_DATA)
    // measures only: the verdict then comes from the count tables
    // (count_tables.h), which hold the CPU's number for the stage's views.
    bool measuredOnly = false;
    long measured = 0;  // the GPU's number (fins emitted)
    long outOf = 0;     // of how many (the mesh's edges)
};

class TrackRenderer {
public:
    virtual ~TrackRenderer() = default;

    // Draws one frame into the off-screen target.
    virtual void render(const Camera& camera, float timeSeconds,
                        const RenderSettings& settings) = 0;
    // The last frame, as a picture, and its size.
    virtual Image read() const = 0;
    // The last frame as RGBA floats, top row first (a float target keeps NaN
    // and Inf, which grading must see).
    virtual std::vector<float> readFloats() const = 0;
    // Pixels of the last frame whose computation reached a TODO stub, as the
    // shader marked them (check targets only); -1 where not counted.
    virtual long todoPixels() const { return -1; }
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
    // One line the user should read about what is drawn (a model's bounds
    // and how it was fitted), empty when there is nothing to say.
    virtual std::string sceneNote() const { return ""; }

    // Fills in what SETTINGS leaves to the scene (the fur's shell count), so
    // that the window's keys start from the values on screen.
    virtual void completeSettings(RenderSettings&) const {}

    // Runs the count check NAME for one view. Throws Error for a name this
    // track does not know.
    virtual CountResult countCheck(const std::string& name, const Camera& camera, float timeSeconds,
                                   const RenderSettings& settings);
};

}  // namespace raylab
