// labs/ is generated from solution/ and must never drift from it.
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

TEST(Labgen, CommittedLabsMatchTheSolution) {
    CommandResult r = runLabgen("--check");
    EXPECT_EQ(r.exitCode, 0) << r.all();
}

TEST(Labgen, DriftIsDetected) {
    ScratchDir labs;
    ASSERT_EQ(runLabgen("--labs " + quote(labs.path())).exitCode, 0);
    ASSERT_EQ(runLabgen("--check --labs " + quote(labs.path())).exitCode, 0);
    // A hand edit to a generated file...
    replaceInFile(labs / "01-raycast/intersect_sphere.glsl", "return NO_HIT;", "return 1.0;");
    CommandResult r = runLabgen("--check --labs " + quote(labs.path()));
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_NE(r.out.find("differs: "), std::string::npos) << r.out;
    // ...and a stray shader file that no solution file produces.
    ASSERT_EQ(runLabgen("--labs " + quote(labs.path())).exitCode, 0);
    writeFile(labs / "01-raycast/extra.glsl", "int x;\n");
    r = runLabgen("--check --labs " + quote(labs.path()));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.out.find("not generated from solution/"), std::string::npos) << r.out;
}

TEST(Labgen, LabsKeepTheTodosAndHideTheSolution) {
    std::string lab = readFile(sourceDir() / "labs/01-raycast/intersect_sphere.glsl");
    EXPECT_NE(lab.find("TODO(01.a)"), std::string::npos);
    EXPECT_NE(lab.find("labTodo();"), std::string::npos);
    EXPECT_EQ(lab.find("sqrt"), std::string::npos) << "the lab must not contain the solution";
    EXPECT_EQ(lab.find("//@"), std::string::npos) << "no markers in students' files";
}
