// The window's fewer-pixels-while-moving policy: full resolution when still,
// a divisor that brings a moving frame near the target time, back to full
// resolution once the camera has settled, and nothing reduced when off.
#include "motion_resolution.h"

#include <gtest/gtest.h>

using raylab::MotionResolution;

namespace {
constexpr double kFullMs = 300.0;  // a full lite frame on llvmpipe, about

// A renderer whose frame time is proportional to its pixels.
double frameMs(int divisor) { return kFullMs / (divisor * divisor); }

// Runs N frames and returns the divisor in force after them.
int run(MotionResolution& m, int frames, bool moving) {
    for (int i = 0; i < frames; ++i) m.update(frameMs(m.divisor()), moving);
    return m.divisor();
}
}  // namespace

TEST(MotionResolution, StillCameraDrawsAtFullResolution) {
    MotionResolution m;
    EXPECT_EQ(run(m, 10, false), 1);
}

TEST(MotionResolution, MovingCameraGetsADivisorThatMeetsTheTarget) {
    MotionResolution m;
    run(m, 3, false);
    const int d = run(m, 20, true);
    EXPECT_GT(d, 1);
    EXPECT_LE(frameMs(d), MotionResolution::kTargetMs * 1.25) << "divisor " << d;
    // Not more reduced than needed: one step finer would miss the target.
    EXPECT_GT(frameMs(d - 1), MotionResolution::kTargetMs * 0.8) << "divisor " << d;
}

TEST(MotionResolution, SettledCameraReturnsToFullResolution) {
    MotionResolution m;
    run(m, 3, false);
    ASSERT_GT(run(m, 5, true), 1);
    // A frame or two of stillness is not enough (the hand may go on) ...
    m.update(frameMs(m.divisor()), false);
    EXPECT_GT(m.divisor(), 1);
    // ... but kSettleSeconds of it is.
    EXPECT_EQ(run(m, 20, false), 1);
}

TEST(MotionResolution, FastSceneIsNeverReduced) {
    MotionResolution m;
    for (int i = 0; i < 20; ++i) m.update(10.0, i > 3);
    EXPECT_EQ(m.divisor(), 1);
}

TEST(MotionResolution, SwitchedOffItNeverReduces) {
    MotionResolution m(false);
    run(m, 3, false);
    EXPECT_EQ(run(m, 20, true), 1);
    m.setEnabled(true);
    EXPECT_GT(run(m, 3, true), 1);
    m.setEnabled(false);
    EXPECT_EQ(m.divisor(), 1);
}

TEST(MotionResolution, SlowerMachineGetsALargerDivisor) {
    MotionResolution m;
    // The first reduced frames take much longer than predicted (a busy
    // machine): the divisor grows until the target is met.
    run(m, 3, false);
    int d = run(m, 1, true);
    for (int i = 0; i < 10; ++i) m.update(4.0 * frameMs(m.divisor()), true);
    EXPECT_GT(m.divisor(), d);
    EXPECT_LE(m.divisor(), MotionResolution::kMaxDivisor);
}

TEST(MotionResolution, ReducedSizeKeepsAtLeastOnePixel) {
    EXPECT_EQ(raylab::reducedSize(800, 3), 266);
    EXPECT_EQ(raylab::reducedSize(5, 8), 1);
    EXPECT_EQ(raylab::reducedSize(640, 1), 640);
}
