// Embree casting a frame's rays (framework/src/bench/embree_caster.h), the
// limit row of `raylab bench`: the rays the reference tracer exports must
// be the frame's rays, and Embree must find what the reference finds for
// them - else the bench would time Embree on a different question. The
// agreement check is shown failing on a wrong scene (a sphere moved, the
// torus gone). Skipped where the build has no Embree.
#include "embree_caster.h"
#include "error.h"
#include "paths.h"
#include "reference_tracer.h"
#include "scene_transform.h"
#include "shader_constants.h"
#include "stage_setup.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace raylab;

namespace {

constexpr int kWidth = 160, kHeight = 120;

struct Frame {
    Scene scene;
    std::vector<ReferenceSample> samples;
    std::vector<TracedRay> rays;
};

const Frame& proFrame() {
    static const Frame frame = [] {
        Frame f;
        f.scene = loadScene(demoSceneFile("pro"));
        ReferenceTracer tracer(f.scene, ReferenceFeatures::forStage(demoStage()), 0.0f,
                               RenderSettings{});
        f.samples = tracer.traceImage(cameraFor(std::nullopt, f.scene), kWidth, kHeight, &f.rays);
        return f;
    }();
    return frame;
}

}  // namespace

TEST(EmbreeRays, TheExportIsEveryRayOfTheFrame) {
    const Frame& f = proFrame();
    const TracedRayCounts c = countRays(f.rays);
    std::size_t traced = 0, glowChecks = 0;
    for (const ReferenceSample& s : f.samples) traced += std::size_t(s.rays);
    for (const TracedRay& r : f.rays) glowChecks += r.kind == TracedRay::Kind::Glow;
    std::printf(
        "[ figure ] pro %dx%d: %zu rays: %zu primary, %zu secondary, %zu glow, %zu shadow\n",
        kWidth, kHeight, c.total(), c.primary, c.secondary, c.glow, c.shadow);
    EXPECT_EQ(c.primary, std::size_t(kWidth * kHeight));
    // The tracer's own count (primary + reflected + refracted per pixel).
    EXPECT_EQ(c.primary + c.secondary, traced);
    EXPECT_GT(c.secondary, c.primary / 10) << "pro has mirrors, glass and gold";
    EXPECT_GT(c.shadow, c.primary) << "pro has 3 lights";
    // Glow rays only where the halo is (glow.glsl tests the halo first).
    EXPECT_GT(glowChecks, 0u);
    EXPECT_LT(glowChecks, c.primary / 2);
    // Shadow rays end at their light; closest rays at T_FAR.
    for (const TracedRay& r : f.rays) {
        ASSERT_NEAR(glm::length(r.dir), 1.0f, 1e-5f);
        if (r.kind == TracedRay::Kind::Shadow) ASSERT_LT(r.tMax, 1e3f);
        else ASSERT_EQ(r.tMax, 1e30f);
    }
}

TEST(Embree, FindsWhatTheReferenceFindsAndFailsOnAWrongScene) {
    if (!embreeBuilt()) GTEST_SKIP() << "Embree not built";
    const Frame& f = proFrame();
    EmbreeCaster caster(f.scene);
    EmbreeAnswers answers;
    caster.cast(f.rays, 2, &answers);
    const double agree = agreementWithReference(f.rays, answers);
    // t of the closest rays where both hit the same object.
    std::size_t same = 0, tClose = 0;
    for (std::size_t i = 0; i < f.rays.size(); ++i) {
        const TracedRay& r = f.rays[i];
        if (r.kind == TracedRay::Kind::Shadow || r.hitId < 0 || r.hitId != answers.ids[i]) continue;
        ++same;
        tClose += std::fabs(answers.t[i] - r.hitT) <= 1e-4f * std::max(1.0f, r.hitT);
    }
    std::printf("[ figure ] Embree %s agrees on %.4f%% of %zu rays; t within 1e-4 relative on "
                "%.4f%% of %zu common hits\n",
                embreeVersion().c_str(), 100.0 * agree, f.rays.size(),
                100.0 * double(tClose) / double(same), same);
    // Measured: 100% (Embree's float spheres and triangles, the reference's
    // shapes for the rest, at the reference's own ray origins).
    EXPECT_GE(agree, 0.9999);
    EXPECT_GE(double(tClose) / double(same), 0.9999);

    // Wrong scenes: the same check must fail.
    Scene moved = f.scene;
    moved.spheres[1].center += glm::vec3(0.3f, 0.0f, 0.0f);
    Scene noTorus = f.scene;
    noTorus.tori.clear();
    for (const Scene* wrong : {&moved, &noTorus}) {
        EmbreeCaster bad(*wrong);
        EmbreeAnswers badAnswers;
        bad.cast(f.rays, 2, &badAnswers);
        const double badAgree = agreementWithReference(f.rays, badAnswers);
        std::printf("[ figure ] wrong scene (%s): agreement %.4f%%\n",
                    wrong == &moved ? "sphere 1 moved" : "no torus", 100.0 * badAgree);
        EXPECT_LT(badAgree, 0.9999);
    }
}

TEST(EmbreeRays, TheWeightCutFrameCastsFewerRaysAndEmbreeAgreesOnThem) {
    const Frame& f = proFrame();
    ReferenceTracer cut(f.scene, ReferenceFeatures::forStage(demoStage()), 0.0f, RenderSettings{});
    cut.setWeightCut(1.0 / 255.0);
    std::vector<TracedRay> rays;
    cut.traceImage(cameraFor(std::nullopt, f.scene), kWidth, kHeight, &rays);
    const TracedRayCounts all = countRays(f.rays), fewer = countRays(rays);
    std::printf("[ figure ] weight cut 1/255: %zu of %zu reflected/refracted rays, %zu of %zu "
                "shadow rays\n",
                fewer.secondary, all.secondary, fewer.shadow, all.shadow);
    EXPECT_EQ(fewer.primary, all.primary);
    EXPECT_LT(fewer.secondary, all.secondary);
    EXPECT_LT(fewer.shadow, all.shadow);  // no shading where no ray goes
    if (!embreeBuilt()) return;
    EmbreeCaster caster(f.scene);
    EmbreeAnswers answers;
    caster.cast(rays, 2, &answers);
    EXPECT_GE(agreementWithReference(rays, answers), 0.9999);
}

// The shared-work lever's glow reuses the primary ray's hit: its frame's
// export is the same rays without the glow rays.
TEST(EmbreeRays, TheSharedWorkFrameCastsNoGlowRays) {
    const Frame& f = proFrame();
    ReferenceTracer shared(f.scene, ReferenceFeatures::forStage(demoStage()), 0.0f,
                           RenderSettings{});
    shared.setGlowSharesPrimaryHit(true);
    std::vector<TracedRay> rays;
    shared.traceImage(cameraFor(std::nullopt, f.scene), kWidth, kHeight, &rays);
    const TracedRayCounts all = countRays(f.rays), fewer = countRays(rays);
    EXPECT_GT(all.glow, 0u);
    EXPECT_EQ(fewer.glow, 0u);
    EXPECT_EQ(fewer.primary, all.primary);
    EXPECT_EQ(fewer.secondary, all.secondary);
    EXPECT_EQ(fewer.shadow, all.shadow);
}

TEST(Embree, TimesACastAndBuildsItsBvh) {
    if (!embreeBuilt()) GTEST_SKIP() << "Embree not built";
    const Frame& f = proFrame();
    EmbreeCaster caster(f.scene);
    EXPECT_GT(caster.buildMs(), 0.0);
    EXPECT_GT(caster.cast(f.rays, 2), 0.0);
    EXPECT_GE(caster.cast({}, 2), 0.0);  // no rays: nothing to do, no crash
}

TEST(Embree, WithoutEmbreeTheCasterSaysSo) {
    if (embreeBuilt()) GTEST_SKIP() << "this build has Embree " << embreeVersion();
    try {
        EmbreeCaster caster(proFrame().scene);
        FAIL() << "a caster without Embree";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("Embree not built"), std::string::npos) << e.what();
    }
}

// Scenes with OBJ meshes and scenes outside the standard frame: Embree gets
// the mesh triangles, and the scene in the frame the reference records its
// rays in (the bench builds it so). Without the meshes, or in the scene's own
// frame, the agreement drops (shown).
TEST(Embree, AgreesOnMeshScenesAndOnScenesMovedIntoTheFrame) {
    if (!embreeBuilt()) GTEST_SKIP() << "Embree not built";
    Scene mesh = loadScene(projectRoot() / "assets/scenes/mesh.json");
    ASSERT_FALSE(mesh.meshes.empty());
    // x 1e4: outside the standard frame's band, so the reference traces it resized.
    const Scene big = transformScene(mesh, SceneTransform{1e4, glm::dvec3(0.0)});
    ASSERT_FALSE(sceneFrame(big).identity());
    ReferenceTracer tracer(big, ReferenceFeatures::forStage(demoStage()), 0.0f, RenderSettings{});
    std::vector<TracedRay> rays;
    tracer.traceImage(cameraFor(std::nullopt, big), 80, 60, &rays);
    const Scene framed = transformScene(big, sceneFrame(big));
    EmbreeAnswers answers;
    EmbreeCaster(framed).cast(rays, 2, &answers);
    EXPECT_GE(agreementWithReference(rays, answers), 0.9999);

    Scene noMeshes = framed;
    noMeshes.meshes.clear();
    EmbreeCaster(noMeshes).cast(rays, 2, &answers);
    EXPECT_LT(agreementWithReference(rays, answers), 0.99);
    EmbreeCaster(big).cast(rays, 2, &answers);
    EXPECT_LT(agreementWithReference(rays, answers), 0.99);
}
