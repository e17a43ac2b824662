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

namespace {

raylab::Image filled(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    raylab::Image img(w, h);
    for (int i = 0; i < w * h; ++i) {
        img.rgba[std::size_t(4 * i)] = r;
        img.rgba[std::size_t(4 * i + 1)] = g;
        img.rgba[std::size_t(4 * i + 2)] = b;
        img.rgba[std::size_t(4 * i + 3)] = 255;
    }
    return img;
}

}  // namespace

// The TODO hint comes from the pixels the shader marked as reaching a stub,
// never from colour: a violet picture with no marked pixel is a wrong colour.
TEST(Diagnose, TodoHintOnlyFromMarkedPixels) {
    raylab::Image expected = filled(40, 30, 40, 40, 40);
    for (int x = 0; x < 40; ++x) expected.rgba[std::size_t(4 * x)] = 90;  // not flat
    raylab::Image violet = filled(40, 30, 200, 40, 200);
    for (int i = 0; i < 80; ++i) violet.rgba[std::size_t(4 * i + 1)] = 200;  // not flat
    raylab::DiagnoseContext unmarked;
    EXPECT_EQ(raylab::diagnose(violet, expected, 8, unmarked).find("TODO"), std::string::npos);
    raylab::DiagnoseContext marked;
    marked.todoPixels = 120;  // 10% of 1200
    EXPECT_NE(raylab::diagnose(violet, expected, 8, marked)
                  .find("10% of the image reaches an "
                        "unfinished TODO"),
              std::string::npos)
        << raylab::diagnose(violet, expected, 8, marked);
    marked.todoPixels = 1;
    EXPECT_NE(raylab::diagnose(violet, expected, 8, marked).find("under 1%"), std::string::npos);
}

// A stage's causes come from its stage.json; without them, the fact alone.
TEST(Diagnose, CausesAreTheStagesOwn) {
    raylab::Image expected = filled(40, 30, 200, 200, 200);
    for (int x = 0; x < 40; ++x) expected.rgba[std::size_t(4 * x)] = 150;
    raylab::Image dark = filled(40, 30, 20, 20, 20);
    for (int i = 0; i < 80; ++i) dark.rgba[std::size_t(4 * i)] = 60;  // not flat
    raylab::DiagnoseContext flatColours;
    const std::string fact = raylab::diagnose(dark, expected, 8, flatColours);
    EXPECT_NE(fact.find("too dark"), std::string::npos) << fact;
    EXPECT_EQ(fact.find('('), std::string::npos) << "no cause without the stage's hints: " << fact;
    raylab::DiagnoseContext shadows;
    shadows.darkerCause = "shadow acne?";
    EXPECT_NE(raylab::diagnose(dark, expected, 8, shadows).find("(shadow acne?)"),
              std::string::npos);
}

// A picture of one colour is said to be one, with the colour, and no more:
// it may be the background (nothing drawn) or a surface gone white.
TEST(Diagnose, OneFlatColourIsStatedNotExplained) {
    raylab::Image expected = filled(40, 30, 30, 40, 60);
    for (int x = 0; x < 40 * 15; ++x) expected.rgba[std::size_t(4 * x)] = 200;  // a picture
    const std::string white = raylab::diagnose(filled(40, 30, 255, 255, 255), expected, 8);
    EXPECT_EQ(white, "the picture is one flat colour, (255, 255, 255), where the expected one has "
                     "a picture");
    EXPECT_EQ(white.find("background"), std::string::npos);
}
