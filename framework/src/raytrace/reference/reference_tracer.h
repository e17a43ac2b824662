#pragma once
// The reference tracer: the shading model of the GPU stages, re-done on the
// CPU in double precision. It is the ground truth of every error figure
// (`raylab bench`, tests/numerics) and the source of the teaching views that
// the GPU does not draw (`--view bounces`, `--view stack`) and of `raylab
// trace`, which prints one pixel's path bounce by bounce.
//
// It follows the GLSL of solution/ line by line (same ray offsets, same
// Schlick Fresnel, same stack discipline, textures sampled like the GPU
// samples them), so where float precision is not the issue a GPU frame and a
// reference frame agree within the graders' tolerance.
#include "camera.h"
#include "image.h"
#include "reference_rays.h"
#include "render_settings.h"
#include "scene.h"
#include "stage_catalog.h"

#include <glm/glm.hpp>

#include <iosfwd>
#include <memory>
#include <vector>

namespace raylab {

// Which parts of the model a stage has: its stage.json "features".
struct ReferenceFeatures {
    bool shading = true;     // 02+: Blinn-Phong (else the flat diffuse colour of 01)
    bool shadows = true;     // 03+: shadow rays
    bool recursion = true;   // 04+: mirror, glass and metal rays on the stack
    bool textures = true;    // 06+: textures, sky box, glow
    bool normalMaps = true;  // 07+
    bool colorModes = true;  // 08
    static ReferenceFeatures forStage(const StageInfo& stage);
};

// What one primary ray found.
struct ReferenceSample {
    glm::dvec3 color{0.0};  // the pixel's colour (after glow and colour mode), not clamped
    double depth = 0.0;     // hit distance t along the primary ray; 0 when it hit nothing
    glm::dvec3 normal{
        0.0};      // unit outward normal at the primary hit (after normal mapping); 0 for none
    int id = -1;   // object id of the primary hit (kind * 2^20 + index, as in GLSL); -1 for none
    int rays = 0;  // rays traced for this pixel (primary, reflected, refracted; not shadow rays)
    int maxStack = 0;            // most rays waiting on the stack at once
    bool stackOverflow = false;  // a refracted ray was dropped because the stack was full
};

struct PrimaryRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 dir{0.0, 0.0, -1.0};  // unit
};

// The primary ray through the centre of pixel (x, y) of a WIDTH x HEIGHT
// image, y = 0 the TOP row of the saved picture - the ray canvas.vert gives
// that fragment, computed in double.
PrimaryRay primaryRay(const Camera& camera, int width, int height, int x, int y);

// SAMPLES (traceImage's) as an 8-bit picture, converted exactly as checks
// and grading convert GPU frames (imageFromFloats: clamp, scale, round);
// *NONFINITE counts NaN/Inf pixels when given.
Image referenceImage(const std::vector<ReferenceSample>& samples, int width, int height,
                     long* nonFinite = nullptr);

class ReferenceTracer {
public:
    // Loads the scene's textures and sky box. Positions of moving objects
    // are taken at TIMESECONDS. Throws Error on a missing picture.
    ReferenceTracer(const Scene& scene, const ReferenceFeatures& features, float timeSeconds,
                    const RenderSettings& settings);
    ~ReferenceTracer();

    // The weight-cut variant of trace.glsl (framework/shaders/variants/
    // weight-cut): reflected and refracted rays whose weight is below CUT
    // in every channel are not traced. 0 (the default): every ray is.
    // For `raylab bench`, to export the rays such a frame casts.
    void setWeightCut(double cut);

    // The shared-work variant (framework/shaders/variants/shared-work): the
    // glow reuses the primary ray's hit instead of casting its own ray. The
    // picture is the same; only the ray export changes (no glow rays).
    void setGlowSharesPrimaryHit(bool shared);

    // Traces one primary ray. With LOG, writes the path bounce by bounce:
    // object hit, t, normal, material, Fresnel weights, what is pushed and
    // popped, the colour added.
    ReferenceSample trace(const PrimaryRay& ray, std::ostream* log = nullptr) const;

    // Every pixel, row-major, row 0 at the top. Uses every core. With RAYS,
    // also every ray the frame casts (primary, reflected, refracted, glow
    // and shadow rays, each with the reference's answer), in pixel order,
    // each pixel's rays in the order the tracer casts them.
    std::vector<ReferenceSample> traceImage(const Camera& camera, int width, int height,
                                            std::vector<TracedRay>* rays = nullptr) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace raylab
