// `raylab check` runs its work in a child process with grading's limits
// (framework/src/classroom/check_sandbox.h): a lab that crashes the shader compiler
// or never finishes gets a one-line cause, and a crash names the file.
#include "test_support.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace raylab::test;

namespace {

// One expression of 200,000 terms, first in intersectSphere: Mesa 22.3's
// GLSL compiler dies on it with a segmentation fault (found by a student run).
std::string hugeExpression() {
    std::ostringstream s;
    s << "\n    float huge = 0.0";
    for (int i = 0; i < 200000; ++i) s << " + ray.dir.x * " << (i % 7) << ".0";
    s << ";\n    if (huge > 1e30) return NO_HIT;\n";
    return s.str();
}

}  // namespace

TEST(CheckSandbox, ACompilerCrashNamesTheFileThatCausesIt) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    const fs::path file = lab / "01-raycast" / "intersect_sphere.glsl";
    std::string text = readFile(file);
    const std::size_t body = text.find('{', text.find("float intersectSphere("));
    ASSERT_NE(body, std::string::npos) << text;
    writeFile(file, text.insert(body + 1, hugeExpression()));

    CommandResult r = runRaylab("check --stage 01 --lab " + quote(lab.path()));
    if (r.exitCode == 1 && r.err.find("crash") == std::string::npos)
        GTEST_SKIP() << "this driver compiles the 200,000-term expression: no crash to contain";
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("intersect_sphere.glsl makes the shader compiler or driver crash"),
              std::string::npos)
        << r.err;

    // The control: the crash is in that file only, and only while it is there.
    writeFile(file, readFile(sourceDir() / "labs/01-raycast/intersect_sphere.glsl"));
    r = runRaylab("check --stage 01 --lab " + quote(lab.path()));
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_EQ(r.err.find("crash"), std::string::npos) << r.err;
}

TEST(CheckSandbox, ACheckThatTakesTooLongIsStoppedWithItsCause) {
    // Functions that each call the one below twice: the compiler inlines
    // 2^14 copies, which takes far longer than a second on any driver.
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    const fs::path file = lab / "01-raycast" / "intersect_sphere.glsl";
    std::string text = readFile(file), slow = "float slow0(float x) { return x * 1.0001 + 0.5; }\n";
    for (int k = 1; k <= 14; ++k)
        slow += "float slow" + std::to_string(k) + "(float x) { return slow" +
                std::to_string(k - 1) + "(x) + slow" + std::to_string(k - 1) +
                "(x * 0.5 + 1.0); }\n";
    const std::size_t at = text.find("float intersectSphere(");
    ASSERT_NE(at, std::string::npos);
    text.insert(text.find('{', at) + 1, "\n    if (slow14(ray.dir.x) > 1e30) return NO_HIT;\n");
    text.insert(at, slow);
    writeFile(file, text);
    CommandResult r = runRaylab("check --stage 01 --timeout 1 --lab " + quote(lab.path()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("raylab check: stage 01-raycast stopped after 1 s (--timeout)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(runRaylab("check --stage 01 --timeout 0").exitCode, 2) << "a timeout must be > 0";
}
