// The page's geometry shaders (no geometry shader in WebGL 2: the rewrite of
// core/geometry_emulation.h, drawn with transform feedback) against real
// geometry shaders, on desktop GL 3.3: every fur stage that has one, on
// every fur scene, from the scene's camera and a grazing one - the same
// primitives (fins, strand segments) and the same pictures. And a mistake in
// fin.geom shows in the emulated pictures as in the real ones.
#include "fur_renderer.h"
#include "image_compare.h"
#include "paths.h"
#include "stage_setup.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace raylab;
using namespace raylab::test;

namespace {

std::vector<std::string> furScenes() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(projectRoot() / "assets/scenes/fur"))
        if (e.path().extension() == ".json") out.push_back("fur/" + e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<Camera> camerasOf(const FurScene& scene) {
    CameraPose grazing = scene.camera;
    grazing.position += glm::vec3(0.0f, 1.2f, 0.0f);
    grazing.pitchDeg -= 30.0f;
    return {Camera(scene.camera, scene.fovYDeg), Camera(grazing, scene.fovYDeg)};
}

struct Drawn {
    Image picture;
    long primitives = 0;
};

Drawn draw(FurRenderer& r, const Camera& camera, const RenderSettings& settings) {
    r.render(camera, 0.4f, settings);
    Drawn d{r.read(), 0};
    d.primitives = settings.furTechnique == 1 ? r.countStrandSegments(camera, 0.4f, settings)
                                              : r.countFins(camera, 0.4f, settings);
    return d;
}

void compareBothWays(const StageInfo& stage, const StageSources& sources, int technique,
                     int* compared) {
    for (const std::string& name : furScenes()) {
        const FurScene scene = loadFurScene(stageSceneFile(name));
        FurRenderer real(stage, sources, scene, 160, 120);
        FurRenderer emulated(stage, sources, scene, 160, 120);
        emulated.setGeometryEmulation(true);
        RenderSettings settings;
        settings.furTechnique = technique;
        for (const Camera& camera : camerasOf(scene)) {
            const Drawn a = draw(real, camera, settings), b = draw(emulated, camera, settings);
            EXPECT_GT(a.primitives, 0) << name;
            EXPECT_EQ(a.primitives, b.primitives) << stage.id << " " << name;
            const ImageDiff diff = compareImages(a.picture, b.picture, 8);
            EXPECT_TRUE(imagesAgree(diff, {})) << stage.id << " " << name << ": " << describe(diff);
            ++*compared;
        }
    }
}

}  // namespace

TEST(GeometryEmulation, FinsDrawAsARealGeometryShaderDrawsThem) {
    ensureGlContext();
    const StageInfo& stage = findStage("f3");
    int compared = 0;
    compareBothWays(stage, solutionSources(stage), 0, &compared);
    std::printf("[ figure   ] emulated fins = real fins in %d scene/camera pairs\n", compared);
}

TEST(GeometryEmulation, StrandsDrawAsARealGeometryShaderDrawsThem) {
    ensureGlContext();
    const StageInfo& stage = findStage("f4");
    int compared = 0;
    compareBothWays(stage, solutionSources(stage), 1, &compared);
    std::printf("[ figure   ] emulated strands = real strands in %d scene/camera pairs\n",
                compared);
}

// A mistake in fin.geom changes the emulated picture as it changes the real one.
TEST(GeometryEmulation, AFinMistakeShowsInBothWays) {
    ensureGlContext();
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    replaceInFile(lab / "f3-fins" / "fin.geom", "vec3 topC = c + vNormal[2] * uFurLength;",
                  "vec3 topC = c + vNormal[1] * uFurLength;");
    const StageInfo& stage = findStage("f3");
    const FurScene scene = loadFurScene(stageSceneFile("fur/coarse.json"));
    const Camera camera(scene.camera, scene.fovYDeg);
    FurRenderer solved(stage, solutionSources(stage), scene, 160, 120);
    FurRenderer real(stage, labSources(stage, lab.path()), scene, 160, 120);
    FurRenderer emulated(stage, labSources(stage, lab.path()), scene, 160, 120);
    emulated.setGeometryEmulation(true);
    const Drawn right = draw(solved, camera, {}), a = draw(real, camera, {}),
                b = draw(emulated, camera, {});
    EXPECT_FALSE(imagesAgree(compareImages(right.picture, a.picture, 8), {}));
    EXPECT_TRUE(imagesAgree(compareImages(a.picture, b.picture, 8), {}));
}
