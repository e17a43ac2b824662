// labs/ is generated from solution/ and must never drift from it.
#include "test_support.h"

#include <gtest/gtest.h>

#include <sstream>

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

namespace {

// The 1-based lines of TEXT that are preprocessor branches (#if ... #endif).
std::vector<int> branchLines(const std::string& text) {
    std::vector<int> found;
    std::istringstream in(text);
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] != '#') continue;
        const std::string directive = line.substr(first, line.find_first_of(" \t(", first) - first);
        for (const char* d : {"#if", "#ifdef", "#ifndef", "#else", "#elif", "#endif"})
            if (directive == d) found.push_back(n);
    }
    return found;
}

}  // namespace

// Students read only what they need: the framework's switches (naive
// numerics, the seed's torus solver, the linear search) live in
// framework/shaders/variants/, so no lab file holds a preprocessor branch.
TEST(Labgen, LabFilesHoldNoPreprocessorBranches) {
    int files = 0;
    for (const auto& e : fs::recursive_directory_iterator(sourceDir() / "labs")) {
        const std::string ext = e.path().extension().string();
        if (ext != ".glsl" && ext != ".frag" && ext != ".vert" && ext != ".geom") continue;
        ++files;
        for (int line : branchLines(readFile(e.path())))
            ADD_FAILURE() << e.path().string() << ":" << line << ": a preprocessor branch";
    }
    EXPECT_GE(files, 40);
}

// The scan finds a switch planted in a lab file.
TEST(Labgen, APreprocessorBranchInALabIsFound) {
    const std::string text = readFile(sourceDir() / "labs/02-shading/intersect_sphere.glsl");
    EXPECT_TRUE(branchLines(text).empty());
    EXPECT_EQ(branchLines(text + "#ifdef RAYLAB_NAIVE_NUMERICS\n  #else\n#endif\n").size(), 3u);
}
