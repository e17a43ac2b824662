// Command-line value formats.
#include "cli_parse.h"
#include "error.h"

#include <gtest/gtest.h>

using namespace raylab;

TEST(CliParse, Size) {
    Size s = parseSize("800x600");
    EXPECT_EQ(s.width, 800);
    EXPECT_EQ(s.height, 600);
    EXPECT_EQ(parseSize("1X1").width, 1);
    for (const char* bad : {"", "800", "800x", "x600", "0x600", "800x0", "-1x5", "800x600x3",
                            "99999x10", "8193x8193", "abcxdef", "1e3x2"})
        EXPECT_THROW(parseSize(bad), Error) << "'" << bad << "' should be rejected";
}

TEST(CliParse, Camera) {
    CameraPose p = parseCamera("1,2.5,-3,90,-10");
    EXPECT_DOUBLE_EQ(p.position.x, 1.0);
    EXPECT_DOUBLE_EQ(p.position.y, 2.5);
    EXPECT_DOUBLE_EQ(p.position.z, -3.0);
    EXPECT_FLOAT_EQ(p.yawDeg, 90.0f);
    EXPECT_FLOAT_EQ(p.pitchDeg, -10.0f);
    for (const char* bad : {"", "1,2,3,4", "1,2,3,4,5,6", "1,2,3,4,", "a,2,3,4,5", "1,,3,4,5",
                            "1,2,3,4,95", "nan,0,0,0,0", "inf,0,0,0,0", "1e9,0,0,0,0"})
        EXPECT_THROW(parseCamera(bad), Error) << "'" << bad << "' should be rejected";
}

TEST(CliParse, SceneScaleAndOffset) {
    EXPECT_EQ(parseSceneScale("1e4"), 1e4);
    EXPECT_EQ(parseSceneScale("0.5"), 0.5);
    for (const char* bad : {"", "0", "-1", "1e-7", "1e9", "nan", "inf", "2x", "1,2"})
        EXPECT_THROW(parseSceneScale(bad), Error) << "'" << bad << "' should be rejected";
    EXPECT_EQ(parseSceneOffset("1e5,0,-2.5"), glm::dvec3(1e5, 0.0, -2.5));
    for (const char* bad : {"", "1,2", "1,2,3,4", "1,2,", "a,0,0", "1,,3", "nan,0,0", "1e9,0,0"})
        EXPECT_THROW(parseSceneOffset(bad), Error) << "'" << bad << "' should be rejected";
}
