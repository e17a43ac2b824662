// A picture must not depend on the scene's size or place (issues 14 and
// 30): the demo scenes lite and pro, resized by factors from 1e-4 to 1e6 and
// moved 1e5 and 1e6 away from the origin by offsets with fractions
// (transformScene, the same function as `raylab render --scene-scale S
// --scene-offset X,Y,Z`), drawn by stage 08's
// solution on the GPU and by the reference tracer, each compared with its
// own picture of the scene as it is:
//   - colour: pixels beyond the graders' tolerance (image_compare.h: no
//     neighbour within 8/255), which must be none;
//   - depth (the hit distance t, divided by the factor): the error in float
//     steps of the depth, over the pixels where both pictures hit something
//     and no neighbour's depth jumps (at an object's outline a pixel may
//     rightly see the object in one picture and the one behind in the
//     other). The 99.9th percentile must be a few float steps.
// Moved far away, the scene keeps its small digits: it is held in double
// and the renderers move its eye to the origin in double before anything
// becomes a float (sceneFrame). Held in float (before issue 30), 1e5 + 0.35
// was rounded to a step of 1/128 and 0.7-1.5% of pro's pixels moved.
// Printed: one table row per scene and transform (the README's accuracy
// section shows it). Without the renderers' standard frame (sceneFrame) the
// GPU's 1e4 row has 4.7% of lite's pixels off and 1e-3 has 1%; the reference
// tracer (whose T_MIN was 1e-4 absolute) lost whole spheres below 1e-3.
#include "debug_views.h"
#include "image_compare.h"
#include "numerics_support.h"
#include "pfm.h"
#include "reference_tracer.h"
#include "scene_transform.h"
#include "stage_renderer.h"
#include "stage_setup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace raylab;
using namespace raylab::numerics;

namespace {

constexpr int kWidth = 160, kHeight = 120;
// Depth error allowed at the 99.9th percentile, in float steps of the depth.
constexpr double kDepthUlps = 8.0;
// Share of pixels allowed beyond the graders' tolerance: 0.1% (19 of 19200).
// Not 0: the standard frame keeps a scene's size only within a band (a
// factor up to ~20 apart for lite at 1e-4), so T_MIN and the ray offsets are
// not exactly the same share of the scene at every factor; the few pixels it
// moves (measured up to 0.08%) sit at contacts and glass edges, and the
// reference tracer, which follows the same model, moves the same ones.
constexpr double kShare = 0.001;

struct Frame {
    Image color;
    std::vector<float> depth;  // 0: nothing hit
};

Frame gpuFrame(const Scene& scene) {
    ensureGlContext();
    const StageInfo& stage = demoStage();
    const Camera camera = cameraFor(std::nullopt, scene);
    StageRenderer color(stage, solutionSources(stage), scene, kWidth, kHeight,
                        PixelFormat::Rgba32F);
    color.render(camera, 0.0f, RenderSettings{});
    Frame f;
    long nonFinite = 0;
    f.color = imageFromFloats(color.target().readFloats(), kWidth, kHeight, &nonFinite);
    EXPECT_EQ(nonFinite, 0);
    GpuViewRenderer depth(GpuView::Depth, stage, solutionSources(stage), scene, kWidth, kHeight);
    depth.render(camera, 0.0f, RenderSettings{});
    const std::vector<float> rgba = depth.readFloats();
    for (std::size_t i = 0; i < rgba.size(); i += 4) f.depth.push_back(rgba[i]);
    return f;
}

Frame referenceFrame(const Scene& scene) {
    ReferenceTracer tracer(scene, ReferenceFeatures::forStage(demoStage()), 0.0f, RenderSettings{});
    const std::vector<ReferenceSample> samples =
        tracer.traceImage(cameraFor(std::nullopt, scene), kWidth, kHeight);
    Frame f;
    f.color = referenceImage(samples, kWidth, kHeight);
    for (const ReferenceSample& s : samples) f.depth.push_back(float(s.depth));
    return f;
}

// Depth is smooth around pixel I: every neighbour within 10% of it.
bool smooth(const std::vector<float>& d, int x, int y) {
    const float c = d[std::size_t(y * kWidth + x)];
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, kWidth - 1),
                      ny = std::clamp(y + dy, 0, kHeight - 1);
            const float n = d[std::size_t(ny * kWidth + nx)];
            if (n <= 0.0f || std::fabs(n - c) > 0.1f * c) return false;
        }
    return true;
}

struct Row {
    double badShare = 0.0;
    int maxDiff = 0;
    double depthP999 = 0.0, depthMax = 0.0;  // float steps
};

Row compare(const Frame& base, const Frame& moved, double scale) {
    Row r;
    const ImageDiff d = compareImages(base.color, moved.color, CompareTolerance{}.channel);
    r.badShare = d.badShare;
    r.maxDiff = d.maxDiff;
    std::vector<double> ulps;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(y * kWidth + x);
            if (base.depth[i] <= 0.0f || moved.depth[i] <= 0.0f) continue;
            if (!smooth(base.depth, x, y)) continue;
            const double expected = base.depth[i];
            ulps.push_back(std::fabs(double(moved.depth[i]) / scale - expected) /
                           floatUlp(expected));
        }
    r.depthP999 = percentile(ulps, 99.9);
    r.depthMax = percentile(ulps, 100.0);
    return r;
}

struct Case {
    double scale;
    glm::dvec3 offset;
    std::string label;
};

const std::vector<Case>& cases() {
    static const std::vector<Case> all = {
        {1e-4, {}, "x 1e-4"},
        {1e-3, {}, "x 1e-3"},
        {1e-2, {}, "x 1e-2"},
        {1e2, {}, "x 1e2"},
        {1e4, {}, "x 1e4"},
        {1e6, {}, "x 1e6"},
        {1.0, glm::dvec3(1e5 + 0.35, -1e5 - 0.123, 1e5 + 0.7), "+ 1e5 (fractions)"},
        {1.0, glm::dvec3(-1e6 - 0.35, 1e6 + 0.1, 1e6 - 0.3), "+ 1e6 (fractions)"},
    };
    return all;
}

void printHeader() {
    static bool printed = false;
    if (printed) return;
    printed = true;
    std::printf(
        "scale table (%dx%d, stage 08 solution; off: pixels beyond 8/255 vs the scene as given;"
        " depth: |t/s - t| in float steps, p99.9 / max; GPU vs ref: the moved scene's GPU picture"
        " against its reference, pixels off / depth p99.9)\n",
        kWidth, kHeight);
    std::printf(
        "| scene | transform | GPU off | GPU depth | reference off | reference depth | GPU vs "
        "ref |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
}

class SceneScale : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(SceneScale, PicturesAndDepthsDoNotDependOnSizeOrPlace) {
    const Scene base = loadScene(demoSceneFile(GetParam()));
    const Frame gpuBase = gpuFrame(base), refBase = referenceFrame(base);
    printHeader();
    for (const Case& c : cases()) {
        const Scene moved = transformScene(base, SceneTransform{c.scale, c.offset});
        const Frame gpuMoved = gpuFrame(moved), refMoved = referenceFrame(moved);
        const Row gpu = compare(gpuBase, gpuMoved, c.scale);
        const Row ref = compare(refBase, refMoved, c.scale);
        const Row gpuVsRef = compare(refMoved, gpuMoved, 1.0);
        std::printf("| %s | %s | %.2f%% (max %d) | %.1f / %.0f | %.2f%% (max %d) | %.1f / %.0f | "
                    "%.2f%% / %.1f |\n",
                    GetParam().c_str(), c.label.c_str(), 100.0 * gpu.badShare, gpu.maxDiff,
                    gpu.depthP999, gpu.depthMax, 100.0 * ref.badShare, ref.maxDiff, ref.depthP999,
                    ref.depthMax, 100.0 * gpuVsRef.badShare, gpuVsRef.depthP999);
        std::fflush(stdout);
        const std::string what = GetParam() + " " + c.label;
        // The moved scene's GPU picture is as close to its reference as ever.
        EXPECT_LE(gpuVsRef.badShare, kShare) << what;
        EXPECT_LE(gpuVsRef.depthP999, kDepthUlps) << what;
        EXPECT_LE(gpu.badShare, kShare) << what << " (GPU)";
        EXPECT_LE(ref.badShare, kShare) << what << " (reference)";
        EXPECT_LE(gpu.depthP999, kDepthUlps) << what << " (GPU)";
        EXPECT_LE(ref.depthP999, kDepthUlps) << what << " (reference)";
    }
}

// The demo's program (specialised, weight cut, shared work, light buffer:
// ShaderVariant::useDemoLevers) at the same scales and places: still within
// the graders' tolerance of the reference tracer. The light buffer's
// margins are shares of the scene's size, and this is where a margin that
// did not scale would show as missing shadows.
TEST_P(SceneScale, TheDemosProgramAgreesWithTheReferenceAtEveryScale) {
    const Scene base = loadScene(demoSceneFile(GetParam()));
    ensureGlContext();
    const StageInfo& stage = demoStage();
    ShaderVariant demo;
    demo.specialized = true;
    demo.useDemoLevers();
    for (const Case& c : cases()) {
        const Scene moved = transformScene(base, SceneTransform{c.scale, c.offset});
        ASSERT_TRUE(demo.usesLightBuffer(moved));
        StageRenderer gpu(stage, solutionSources(stage), moved, kWidth, kHeight,
                          PixelFormat::Rgba32F, "", demo);
        gpu.render(cameraFor(std::nullopt, moved), 0.0f, RenderSettings{});
        long nonFinite = 0;
        const Image picture =
            imageFromFloats(gpu.target().readFloats(), kWidth, kHeight, &nonFinite);
        EXPECT_EQ(nonFinite, 0);
        const ImageDiff d =
            compareImages(referenceFrame(moved).color, picture, CompareTolerance{}.channel);
        std::printf("[ figure ] %s %s: the demo's program against the reference: %.3f%% of "
                    "pixels off (max %d/255)\n",
                    GetParam().c_str(), c.label.c_str(), 100.0 * d.badShare, d.maxDiff);
        EXPECT_LE(d.badShare, kShare) << GetParam() << " " << c.label;
    }
}

INSTANTIATE_TEST_SUITE_P(DemoScenes, SceneScale, ::testing::Values("lite", "pro"));

// The command line does the same: `raylab render --scene-scale S` draws the
// resized scene, and its depth view measures in the new units.
TEST(SceneScaleCommand, RenderResizesTheSceneAndItsDepths) {
    raylab::test::ScratchDir dir;
    const std::string scene =
        raylab::test::quote((raylab::test::sourceDir() / "assets/scenes/stage02.json").string());
    auto depth = [&](const std::string& name, const std::string& extra) {
        const auto out = dir / (name + ".pfm");
        const auto r = raylab::test::runRaylab(
            "render --stage 03 --solution --size 64x48 --scene " + scene + " --view depth --out " +
            raylab::test::quote(out.string()) + extra);
        EXPECT_EQ(r.exitCode, 0) << r.all();
        return decodePfm(raylab::test::readFile(out), out.string());
    };
    const FloatImage plain = depth("plain", "");
    const FloatImage big = depth("big", " --scene-scale 1e4 --scene-offset 1e3,0,0");
    ASSERT_EQ(plain.values.size(), big.values.size());
    int hits = 0;
    for (std::size_t i = 0; i < plain.values.size(); ++i) {
        if (plain.values[i] <= 0.0f) continue;
        ++hits;
        EXPECT_NEAR(big.values[i] / 1e4, plain.values[i], 1e-4 * plain.values[i]) << i;
    }
    EXPECT_GT(hits, 100);
}

// `raylab check --scene-scale S --scene-offset X,Y,Z` draws every check view
// resized and moved, and the pictures still match the stored references
// (drawn at the scenes' own size) within the graders' tolerance.
TEST(SceneScaleCommand, CheckViewsMatchTheReferencesAtAnyScale) {
    const std::string references =
        raylab::test::quote((raylab::test::sourceDir() / "tests/reference/03-shadows").string());
    for (const char* transform :
         {"--scene-scale 1e-3", "--scene-scale 1e4 --scene-offset 1e5,0,-1e5",
          "--scene-offset 1000000.35,-999999.7,0.123"}) {
        const auto r = raylab::test::runRaylab("check --stage 03 --solution --against " +
                                               references + " " + transform);
        EXPECT_EQ(r.exitCode, 0) << transform << "\n" << r.all();
        EXPECT_NE(r.out.find(", 0 failed"), std::string::npos) << transform << "\n" << r.out;
    }
}
