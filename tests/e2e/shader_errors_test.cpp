// A student's shader error is reported at the student's file and line, the
// program refuses to run, and no image is written.
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

namespace {
// Puts BROKEN as a new line after the line containing ANCHOR in FILE of a solved lab,
// and returns the 1-based line number the broken line ends up on.
int breakLab(const fs::path& lab, const std::string& file, const std::string& anchor,
             const std::string& broken) {
    fs::path path = lab / "01-raycast" / file;
    std::string text = readFile(path);
    std::size_t at = text.find(anchor);
    EXPECT_NE(at, std::string::npos);
    std::size_t eol = text.find('\n', at);
    text.insert(eol + 1, broken + "\n");
    writeFile(path, text);
    return int(std::count(text.begin(), text.begin() + long(eol) + 1, '\n')) + 1;
}
}  // namespace

TEST(ShaderErrors, SyntaxErrorIsMappedToTheStudentsFileAndLine) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    int line = breakLab(lab.path(), "intersect_sphere.glsl", "float c = dot(oc, oc)",
                        "    float h2 = b * b - c  // missing semicolon");
    fs::path out = lab / "out.png";
    CommandResult r =
        runRaylab("render --stage 01 --lab " + quote(lab.path()) + " --out " + quote(out));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    // The compiler notices the missing ';' on the next line, which is in the same file.
    std::string where = "01-raycast/intersect_sphere.glsl:" + std::to_string(line + 1) + ":";
    EXPECT_NE(r.err.find(where), std::string::npos) << "expected " << where << " in:\n" << r.err;
    EXPECT_NE(r.err.find("raylab: error: shader does not compile: "), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(ShaderErrors, UndeclaredNameIsReportedOnItsOwnLine) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    int line = breakLab(lab.path(), "find_closest.glsl", "hit = Hit(T_FAR, -1);",
                        "    float oops = undefinedThing;");
    CommandResult r = runRaylab("render --stage 01 --lab " + quote(lab.path()) + " --out " +
                                quote(lab / "o.png"));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    std::string where = "01-raycast/find_closest.glsl:" + std::to_string(line) + ":";
    EXPECT_NE(r.err.find(where), std::string::npos) << "expected " << where << " in:\n" << r.err;
    EXPECT_NE(r.err.find("undefinedThing"), std::string::npos) << r.err;
}

TEST(ShaderErrors, MissingIncludeNamesTheIncludingLine) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    replaceInFile(lab / "01-raycast/main.frag", "#include \"find_closest.glsl\"",
                  "#include \"find_closets.glsl\"");
    CommandResult r = runRaylab("render --stage 01 --lab " + quote(lab.path()) + " --out " +
                                quote(lab / "o.png"));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("01-raycast/main.frag:7: cannot find shader file \"find_closets.glsl\""),
              std::string::npos)
        << r.err;
}
