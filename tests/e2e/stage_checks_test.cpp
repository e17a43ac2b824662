// For every available stage, through the `raylab` binary:
//  - the solution matches the committed reference images (tests/reference/<stage>/);
//  - the untouched lab fails the check (proof that the check can fail);
//  - a fully solved copy of the lab passes, with no open TODOs;
//  - every known mistake in tests/mistakes/<stage>/ fails on the views it names.
// A new stage gets these tests by adding its references and mistakes.
// Metric and tolerance: tests/README.md ("How images are compared").
#include "check_report.h"
#include "stage_catalog.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>

using namespace raylab::test;

namespace {

std::vector<std::string> availableStages() {
    std::vector<std::string> ids;
    for (const raylab::StageInfo& s : raylab::allStages()) ids.push_back(s.id);
    return ids;
}

class StageChecks : public ::testing::TestWithParam<std::string> {
protected:
    const std::string& stage() const { return GetParam(); }
    std::string stageArg() const { return "--stage " + stage(); }
};

}  // namespace

TEST_P(StageChecks, SolutionMatchesTheCommittedReferenceImages) {
    fs::path refs = sourceDir() / "tests/reference" / stage();
    ASSERT_TRUE(fs::is_directory(refs))
        << "make them with: build/raylab check " << stageArg() << " --solution --save " << refs;
    CommandResult r = runRaylab("check " + stageArg() + " --solution --against " + quote(refs));
    EXPECT_EQ(r.exitCode, 0) << r.all();
    EXPECT_TRUE(failedViews(r.out).empty()) << r.out;
}

TEST_P(StageChecks, UntouchedLabFailsAndListsItsOpenTodos) {
    CommandResult r = runRaylab("check " + stageArg() + " --lab");
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_FALSE(failedViews(r.out).empty()) << r.out;
    EXPECT_NE(r.err.find("open TODO"), std::string::npos) << r.err;
    // The shader marks the pixels that reach a stub; the hint reports them.
    EXPECT_NE(r.out.find("of the image reaches an unfinished TODO"), std::string::npos) << r.out;
}

TEST_P(StageChecks, SolvedLabCopyPassesWithNoOpenTodos) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    CommandResult r = runRaylab("check " + stageArg() + " --lab " + quote(lab.path()));
    EXPECT_EQ(r.exitCode, 0) << r.all();
    EXPECT_EQ(r.err.find("open TODO"), std::string::npos) << r.err;
}

// Each file in tests/mistakes/<stage>/ is a typical mistake, written as text
// replacements in a solved copy of the lab. The check must fail on exactly the checks
// the file names under "caught_by".
TEST_P(StageChecks, EveryKnownMistakeIsCaught) {
    fs::path dir = sourceDir() / raylab::findStage(stage()).mistakes;
    ASSERT_TRUE(fs::is_directory(dir)) << "every stage needs a mistakes catalogue: " << dir;
    int mistakes = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        auto spec = nlohmann::json::parse(readFile(entry.path()));
        SCOPED_TRACE(entry.path().filename().string() + ": " + spec["mistake"].get<std::string>());
        EXPECT_EQ(spec["stage"], stage());
        ScratchDir lab;
        writeSolvedLabs(lab.path());
        for (const auto& pair : spec["replace"])
            replaceInFile(lab / stage() / spec["file"].get<std::string>(), pair[0], pair[1]);
        CommandResult r = runRaylab("check " + stageArg() + " --lab " + quote(lab.path()));
        EXPECT_EQ(r.exitCode, 1) << r.all();
        // No stub is left, so no hint may blame one (a violet sphere is not
        // TODO stripes: stage 02's `inside` view once said so).
        EXPECT_EQ(r.out.find("unfinished TODO"), std::string::npos) << r.out;
        // Exactly the checks the file names: the class summary of `raylab
        // grade` matches failures against these sets.
        std::vector<std::string> failed = failedViews(r.out);
        std::vector<std::string> expected = spec["caught_by"].get<std::vector<std::string>>();
        std::sort(failed.begin(), failed.end());
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(failed, expected) << "caught_by must list every check it fails, and only those\n"
                                    << r.out;
        // Exactly the causes the file accepts: a hint that names a cause the
        // mistake does not have (or misses the one it has) fails here.
        EXPECT_EQ(raylab::causesNamed(r.out, raylab::findStage(stage())),
                  spec["hints"].get<std::vector<std::string>>())
            << "hints must list every cause the check's hints name, and only those\n"
            << r.out;
        ++mistakes;
    }
    EXPECT_GE(mistakes, 2) << "at least two typical mistakes per stage";
}

INSTANTIATE_TEST_SUITE_P(AllStages, StageChecks, ::testing::ValuesIn(availableStages()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string name = param.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// The TODO hint comes from the pixels the shader marks, not from the list of
// open TODOs nor from magenta: a lab with a stub that no pixel reaches and a
// real mistake elsewhere hears about the mistake. (Stage 02's `inside` view is
// inside a violet sphere, which a colour detector took for stripes.)
TEST(TodoHints, AnOpenTodoThatNoPixelReachesIsNotBlamed) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    const fs::path shading = lab / "02-shading" / "blinn_phong.glsl";
    // The ambient term added once per light, and an open stub on a path no
    // pixel takes (no material has a negative exponent).
    replaceInFile(shading, "    color += m.ambient;\n",
                  "    if (m.shininess < -1.0) labTodo();  // TODO(02.x): never reached\n");
    replaceInFile(shading, "color += uLightColors[i] * m.diffuse * lambert;",
                  "color += m.ambient + uLightColors[i] * m.diffuse * lambert;");
    CommandResult r = runRaylab("check --stage 02 --lab " + quote(lab.path()));
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_NE(r.err.find("1 open TODO"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("unfinished TODO"), std::string::npos) << r.out;
    // The mistake's evidence is blinnPhong's failing cases: the views say
    // what their pictures show and point there, naming no usual cause.
    EXPECT_NE(r.out.find("FAIL blinnPhong"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("too bright\n"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("ambient added once per light"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("note: the function check blinnPhong failed above"), std::string::npos)
        << r.out;

    // The control: the same stub on every pixel's path is reported.
    replaceInFile(shading, "if (m.shininess < -1.0) labTodo();", "labTodo();");
    r = runRaylab("check --stage 02 --lab " + quote(lab.path()));
    EXPECT_NE(r.out.find("100% of the image reaches an unfinished TODO"), std::string::npos)
        << r.out;
}

// The hints' test can fail: stage 03's six shadow-ray mistakes each get a
// cause of their own (no entry accepts another's), and a usual cause of the
// stage printed beside them would be seen.
TEST(MistakeHints, EachShadowRayMistakeNamesItsOwnCause) {
    const raylab::StageInfo& stage = raylab::findStage("03-shadows");
    std::map<std::string, std::vector<std::string>> named;
    for (const auto& entry : fs::directory_iterator(sourceDir() / stage.mistakes)) {
        auto spec = nlohmann::json::parse(readFile(entry.path()));
        ScratchDir lab;
        writeSolvedLabs(lab.path());
        for (const auto& pair : spec["replace"])
            replaceInFile(lab / stage.id / spec["file"].get<std::string>(), pair[0], pair[1]);
        CommandResult r = runRaylab("check --stage 03 --lab " + quote(lab.path()));
        const auto causes = raylab::causesNamed(r.out, stage);
        EXPECT_EQ(causes.size(), 1u) << entry.path().filename() << "\n" << r.out;
        named[entry.path().stem().string()] = causes;
        EXPECT_EQ(raylab::causesNamed(r.out + "\nhint: too dark (" + stage.hintDarker + ")", stage),
                  [&] {
                      auto with = causes;
                      with.push_back("darker");
                      std::sort(with.begin(), with.end());
                      return with;
                  }())
            << "a usual cause printed beside the diagnosis is seen";
    }
    ASSERT_EQ(named.size(), 6u);
    for (const auto& [a, causesA] : named)
        for (const auto& [b, causesB] : named)
            if (a != b) {
                EXPECT_NE(causesA, causesB) << a << " and " << b << " name the same cause";
            }
}
