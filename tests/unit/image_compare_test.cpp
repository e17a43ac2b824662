// The image metric shared by tests, `raylab check` and grading.
#include "image_compare.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {
Image disc(int w, int h, float cx, float cy, float r, std::uint8_t red) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.pixel(x, y);
            float dx = float(x) - cx, dy = float(y) - cy;
            bool inside = dx * dx + dy * dy <= r * r;
            p[0] = inside ? red : 20;
            p[1] = inside ? 40 : 160;
            p[2] = 90;
            p[3] = 255;
        }
    return img;
}
const CompareTolerance kTol;
}  // namespace

TEST(ImageCompare, IdenticalImagesAgree) {
    Image a = disc(64, 48, 30, 20, 10, 200);
    ImageDiff d = compareImages(a, a, kTol.channel);
    EXPECT_EQ(d.badPixels, 0);
    EXPECT_EQ(d.maxDiff, 0);
    EXPECT_TRUE(imagesAgree(d, kTol));
}

TEST(ImageCompare, OnePixelEdgeShiftIsNotADifference) {
    ImageDiff d =
        compareImages(disc(64, 48, 30, 20, 10, 200), disc(64, 48, 31, 20, 10, 200), kTol.channel);
    EXPECT_EQ(d.badPixels, 0) << describe(d);
}

TEST(ImageCompare, SmallColourNoiseWithinToleranceAgrees) {
    ImageDiff d =
        compareImages(disc(64, 48, 30, 20, 10, 200),
                      disc(64, 48, 30, 20, 10, std::uint8_t(200 - kTol.channel)), kTol.channel);
    EXPECT_TRUE(imagesAgree(d, kTol)) << describe(d);
}

TEST(ImageCompare, WrongColourOrMovedObjectDisagrees) {
    Image a = disc(64, 48, 30, 20, 10, 200);
    ImageDiff colour = compareImages(a, disc(64, 48, 30, 20, 10, 150), kTol.channel);
    EXPECT_FALSE(imagesAgree(colour, kTol)) << describe(colour);
    ImageDiff moved = compareImages(a, disc(64, 48, 34, 20, 10, 200), kTol.channel);
    EXPECT_FALSE(imagesAgree(moved, kTol)) << describe(moved);
    ImageDiff bigger = compareImages(a, disc(64, 48, 30, 20, 12, 200), kTol.channel);
    EXPECT_FALSE(imagesAgree(bigger, kTol)) << describe(bigger);
}

TEST(ImageCompare, DifferentSizesDisagree) {
    ImageDiff d = compareImages(Image(4, 4), Image(4, 5), kTol.channel);
    EXPECT_FALSE(d.sameSize);
    EXPECT_FALSE(imagesAgree(d, kTol));
}
