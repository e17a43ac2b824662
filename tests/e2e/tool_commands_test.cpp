// `raylab compare` (the graders' comparison as a command) and `raylab shader`
// (the assembled program the web build must reproduce).
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

TEST(CompareCommand, AgreesWithItselfAndDiffersFromAnotherView) {
    const fs::path ref = sourceDir() / "tests/reference/01-raycast";
    CommandResult same =
        runRaylab("compare " + quote(ref / "front.png") + " " + quote(ref / "front.png"));
    EXPECT_EQ(same.exitCode, 0) << same.all();
    EXPECT_NE(same.out.find("agrees (0.00% of pixels differ"), std::string::npos) << same.out;

    ScratchDir dir;
    CommandResult other =
        runRaylab("compare " + quote(ref / "front.png") + " " + quote(ref / "inside.png") +
                  " --heat-map " + quote(dir / "heat.png"));
    EXPECT_EQ(other.exitCode, 1) << other.all();
    EXPECT_NE(other.out.find("DIFFERS"), std::string::npos) << other.out;
    EXPECT_TRUE(fs::exists(dir / "heat.png"));
}

TEST(CompareCommand, PicturesOfTwoSizesAreAOneLineError) {
    CommandResult r = runRaylab("compare " + quote(sourceDir() / "labs/01-raycast/expected.png") +
                                " " + quote(sourceDir() / "tests/reference/01-raycast/front.png"));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("is 480x360 but"), std::string::npos) << r.err;
    CommandResult missing = runRaylab("compare nowhere.png nowhere.png");
    EXPECT_EQ(missing.exitCode, 2) << missing.all();
}

TEST(ShaderCommand, PrintsTheSpecialisedProgramAndItsOrigins) {
    CommandResult r = runRaylab("shader --stage 08 --solution");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_EQ(r.out.rfind("#version 330 core\n", 0), 0u);
    EXPECT_NE(r.out.find("#define SCENE_BAKED"), std::string::npos);
    EXPECT_NE(r.out.find("assets/scenes/lite.json"), std::string::npos);

    CommandResult es = runRaylab("shader --stage 01 --solution --es --origins");
    ASSERT_EQ(es.exitCode, 0) << es.all();
    EXPECT_EQ(es.out.rfind("<raylab>:1\t#version 300 es\n", 0), 0u) << es.out.substr(0, 80);
    EXPECT_NE(es.out.find("solution/01-raycast/intersect_sphere.glsl:"), std::string::npos);

    CommandResult generic = runRaylab("shader --stage 08 --solution --generic");
    ASSERT_EQ(generic.exitCode, 0) << generic.all();
    EXPECT_EQ(generic.out.find("#define SCENE_BAKED"), std::string::npos);
    EXPECT_EQ(generic.out.find("The scene, compiled in"), std::string::npos);
}

TEST(ShaderCommand, RefusesAFurStage) {
    CommandResult r = runRaylab("shader --stage f2 --solution");
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("raylab shader"), std::string::npos) << r.err;
}
