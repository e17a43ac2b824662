// A guide's with-solution and without-solution blocks (lab_folder.h): the
// template's labs keep what needs the solution and leave out what a student
// repository says instead; a student repository the other way round; every
// guide of the course is well formed and, for a student repository, names no
// command its build refuses or lacks, nor the reference tracer it lacks.
#include "error.h"
#include "lab_folder.h"
#include "paths.h"
#include "stage_catalog.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <regex>
#include <set>

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

// The commands of a student repository's build: the cmd_*.cpp files that
// framework/src/cli/CMakeLists.txt compiles when RAYLAB_STUDENT is on.
std::set<std::string> studentBuildCommands() {
    const std::string cmake =
        readTextFile(projectRoot() / "framework" / "src" / "cli" / "CMakeLists.txt");
    const std::size_t at = cmake.find("if(RAYLAB_STUDENT)");
    const std::size_t end = cmake.find("else()", at);
    EXPECT_NE(at, std::string::npos);
    const std::string block = cmake.substr(at, end - at);
    std::set<std::string> commands;
    const std::regex file("cmd_([a-z_]+)\\.cpp");
    for (auto m = std::sregex_iterator(block.begin(), block.end(), file);
         m != std::sregex_iterator(); ++m) {
        std::string name = (*m)[1];
        std::replace(name.begin(), name.end(), '_', '-');
        commands.insert(name);
    }
    return commands;
}

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
                 {"--solution", "--reference", "raylab demo", "-solution -->", "reference tracer"})
                EXPECT_EQ(left.find(refused), std::string::npos) << stage.id << " says " << refused;
            // Every command the guide has the student run (`raylab X` or
            // build/raylab X) is one the student build has; the graders'
            // command is only named, as the instructor's.
            const std::set<std::string> commands = studentBuildCommands();
            const std::regex run("(?:build/|`)raylab ([a-z-]+)");
            std::string named = left;
            for (std::size_t at;
                 (at = named.find("grades with `raylab grade`")) != std::string::npos;)
                named.erase(at, std::strlen("grades with `raylab grade`"));
            for (auto m = std::sregex_iterator(named.begin(), named.end(), run);
                 m != std::sregex_iterator(); ++m)
                EXPECT_TRUE(commands.count((*m)[1]))
                    << stage.id << " has students run " << m->str();
        }
}

TEST(GuideSolutionBlocks, TheStudentBuildsCommandsAreReadFromItsBuildFile) {
    // The control for the check above: the list is the student build's,
    // which has check and trace but not bench or rays.
    const std::set<std::string> commands = studentBuildCommands();
    EXPECT_TRUE(commands.count("check") && commands.count("trace") && commands.count("shader"));
    EXPECT_FALSE(commands.count("bench") || commands.count("rays") || commands.count("demo"));
}
