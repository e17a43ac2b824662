#include "grade_views.h"

#include "json_reader.h"
#include "paths.h"
#include "stage_setup.h"

#include <cstdint>

namespace raylab {

namespace {

// splitmix64: a tiny generator with a fully specified output.
struct SeededRandom {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    float uniform(float lo, float hi) {
        return lo + (hi - lo) * float(double(next() >> 11) * (1.0 / 9007199254740992.0));
    }
};

// The scene file's own camera (views without a pose use it).
CameraPose sceneCamera(const std::string& sceneFile) {
    return loadSceneCamera(stageSceneFile(sceneFile)).pose;
}

std::uint64_t stageHash(const std::string& id) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (char c : id) h = (h ^ std::uint8_t(c)) * 1099511628211ull;
    return h;
}

}  // namespace

std::vector<CheckView> gradingViews(const StageInfo& stage, unsigned seed, int count) {
    std::vector<CheckView> views = stage.checkViews;
    // Seeded views are small moves away from the check views (a random pose
    // anywhere would mostly look at nothing): the camera shifts by up to 0.4
    // units, turns by up to 10 degrees, and the clock moves. Any check view
    // can be the start, with its settings (depth, colour mode...).
    if (stage.checkViews.empty()) return views;
    std::vector<const CheckView*> posed;
    for (const CheckView& v : stage.checkViews) posed.push_back(&v);
    SeededRandom rng{stageHash(stage.id) ^ (std::uint64_t(seed) * 0x2545f4914f6cdd1dull)};
    for (int i = 0; i < count; ++i) {
        const CheckView& base = *posed[rng.next() % posed.size()];
        CheckView v = base;
        v.name = "seeded-" + std::to_string(i + 1);
        v.base = base.name;  // it weighs as much as its base (stage_grading.h)
        CameraPose pose =
            base.pose ? *base.pose : sceneCamera(base.scene.empty() ? stage.scene : base.scene);
        pose.position +=
            glm::vec3(rng.uniform(-0.4f, 0.4f), rng.uniform(-0.2f, 0.2f), rng.uniform(-0.4f, 0.4f));
        pose.yawDeg += rng.uniform(-10.0f, 10.0f);
        pose.pitchDeg += rng.uniform(-6.0f, 6.0f);
        v.pose = pose;
        v.time = base.time + rng.uniform(0.0f, 2.0f);
        v.why = "seeded variation of view '" + base.name + "': " + base.why;
        views.push_back(v);
    }
    return views;
}

}  // namespace raylab
