// The lab guides (labs/<stage>/README.md) send students only to what they
// have: their lab folders, the framework and the assets, and `raylab`. The
// course's tests, the solution and the instructors' tools are not theirs
// (`raylab handout` gives them the released labs), so a guide states what a
// test measured instead of naming the test.
#include "test_support.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

using namespace raylab::test;

namespace {

// The places a guide may not point at: the tests, the solution, the tools,
// and running the test suite.
const std::regex kNotTheirs(
    R"((^|[^A-Za-z0-9_./-])(tests/|solution/|tools/|build/tests/)[A-Za-z0-9_.*/<>-]*|\bctest\b)");

std::vector<std::string> badReferences(const std::string& text) {
    std::vector<std::string> found;
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        for (std::sregex_iterator it(line.begin(), line.end(), kNotTheirs), end; it != end; ++it)
            found.push_back("line " + std::to_string(n) + ": " + it->str());
    return found;
}

}  // namespace

TEST(LabGuides, NameOnlyFilesStudentsHave) {
    int guides = 0;
    for (const auto& e : fs::directory_iterator(sourceDir() / "labs")) {
        const fs::path guide = e.path() / "README.md";
        if (!fs::exists(guide)) continue;
        ++guides;
        for (const std::string& bad : badReferences(readFile(guide)))
            ADD_FAILURE() << fs::relative(guide, sourceDir()).string() << " " << bad;
    }
    EXPECT_GE(guides, 12);
}

TEST(LabGuides, TheCheckFindsWhatItLooksFor) {
    EXPECT_EQ(badReferences("see `tests/numerics/sphere_test.cpp`").size(), 1u);
    EXPECT_EQ(badReferences("the views are in solution/05-primitives/stage.json").size(), 1u);
    EXPECT_EQ(badReferences("run ctest -L numerics").size(), 1u);
    EXPECT_EQ(badReferences("written by tools/scenes/make_demo_scenes.py").size(), 1u);
    EXPECT_TRUE(badReferences("raylab check --stage 01; framework/shaders/ray.glsl; "
                              "assets/scenes/lite.json; labs/01-raycast/tests.txt")
                    .empty());
}
