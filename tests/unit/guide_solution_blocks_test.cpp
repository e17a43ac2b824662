// A guide's with-solution and without-solution blocks (lab_folder.h): the
// template's labs keep what needs the solution and leave out what a student
// repository says instead; a student repository the other way round; every
// guide of the course is well formed and, for a student repository, names no
// command its build refuses.
#include "error.h"
#include "lab_folder.h"
#include "stage_catalog.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {

const std::string kGuide = "intro\n"
                           "<!-- with-solution -->\n"
                           "raylab run --stage 01 --solution\n"
                           "<!-- /with-solution -->\n"
                           "<!-- without-solution -->\n"
                           "your repository holds no solution\n"
                           "<!-- /without-solution -->\n"
                           "<!-- open -->\n"
                           "open text\n"
                           "<!-- with-solution -->\n"
                           "open and solution\n"
                           "<!-- /with-solution -->\n"
                           "<!-- /open -->\n"
                           "end\n";

}  // namespace

TEST(GuideSolutionBlocks, KeptInTheTemplateLeftOutOfAStudentRepository) {
    EXPECT_EQ(guideAtLevel(kGuide, Level::Guided, "g.md"),
              "intro\nraylab run --stage 01 --solution\nend\n");
    EXPECT_EQ(guideAtLevel(kGuide, Level::Open, "g.md"),
              "intro\nraylab run --stage 01 --solution\nopen text\nopen and solution\nend\n");
    EXPECT_EQ(guideAtLevel(kGuide, Level::Guided, "g.md", SolutionText::LeaveOut),
              "intro\nyour repository holds no solution\nend\n");
    EXPECT_EQ(guideAtLevel(kGuide, Level::Open, "g.md", SolutionText::LeaveOut),
              "intro\nyour repository holds no solution\nopen text\nend\n");
}

TEST(GuideSolutionBlocks, AMalformedBlockIsAnErrorWithFileAndLine) {
    const std::pair<const char*, const char*> bad[] = {
        {"a\n<!-- with-solution -->\nb\n", "g.md:2: <!-- with-solution --> not closed"},
        {"<!-- /with-solution -->\n", "g.md:1: <!-- /with-solution --> closes no block"},
        {"<!-- with-solution -->\n<!-- /without-solution -->\n", "g.md:2:"},
        {"<!-- with-solution -->\n<!-- without-solution -->\n", "g.md:2: <!-- without-solution "
                                                                "--> inside"},
        {"<!-- with-solution -->\n## 4. A heading\n<!-- /with-solution -->\n",
         "g.md:2: a heading inside"},
    };
    for (const auto& [text, why] : bad) {
        try {
            guideAtLevel(text, Level::Guided, "g.md", SolutionText::LeaveOut);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
    }
}

TEST(GuideSolutionBlocks, NoStudentRepositoryGuideNamesWhatItsBuildRefuses) {
    for (const StageInfo& stage : allStages())
        for (Level level : {Level::Guided, Level::Open}) {
            const std::string kept = stageGuide(stage, level, stage.grading);
            const std::string left =
                stageGuide(stage, level, stage.grading, SolutionText::LeaveOut);
            // (The control: the template's guides do send their students there.)
            EXPECT_TRUE(kept.find("--solution") != std::string::npos ||
                        kept.find("--reference") != std::string::npos)
                << stage.id;
            for (const char* refused :
                 {"--solution", "--reference", "raylab demo", "-solution -->"})
                EXPECT_EQ(left.find(refused), std::string::npos) << stage.id << " says " << refused;
        }
}
