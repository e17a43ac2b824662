// `raylab student-repo` (framework/src/cli/cmd_student_repo.cpp): a
// repository for stages 01-03 written, committed with git and cloned as a
// student clones it, then built and used with its README's commands as
// written. Then:
//  - the answer search of the page's bundle, applied to it (and to its C++:
//    no reference tracer, no reference or stand-in of a check), finds
//    nothing (no scene, picture or mesh of a stage not released either),
//    and finds each of three planted answers and a planted texture;
//  - its check passes a solved lab and fails the lab as handed out;
//  - each catalogued mistake of 01-03 fails exactly the checks, with exactly
//    the hints, that the instructors' build gives it (tests/mistakes:
//    "caught_by", "hints", which stage_checks_test.cpp holds that build
//    to), and the first of each stage gets the report the instructors'
//    build gives against the same pictures, word for word, score included
//    (the score's handed-out rule reads the pictures the repository ships);
//  - what needs the solution is refused in one line that says why;
//  - a second release (01-04) reaches the clone through `git pull` and
//    leaves the student's own work as it was; a release that drops a stage
//    is refused.
// One repository for the whole file, which runs as one ctest test (label
// student-repo): its build takes about a minute.
#include "check_report.h"
#include "mistake_catalog.h"
#include "stage_catalog.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <sstream>

using namespace raylab::test;

namespace {

const char* const kGit = "git -c user.name=course -c user.email=course@example.org ";

// The clone's own raylab, where its README's install.sh builds it (a folder
// of the student repository, not of the build under test).
const std::string kStudentRaylab = (fs::path("build") / "raylab").string();

class StudentRepo : public ::testing::Test {
protected:
    static ScratchDir* dir;
    static fs::path origin() { return dir->path() / "origin"; }  // the course's
    static fs::path clone() { return dir->path() / "clone"; }    // a student's
    static std::string built;  // what went wrong making or building it, if anything

    static void SetUpTestSuite() {
        dir = new ScratchDir;
        CommandResult r =
            runRaylab("student-repo --stages 01-03 --out " + quote(origin().string()));
        if (r.exitCode != 0) return void(built = "student-repo: " + r.all());
        r = runCommand("cd " + quote(origin().string()) + " && git init -q && " + kGit +
                       "add -A && " + kGit + "commit -qm 'Stages 01-03' && git clone -q . " +
                       quote(clone().string()));
        if (r.exitCode != 0) return void(built = "git: " + r.all());
        // Built as its README says (the first test runs every README command).
        r = runCommand("cd " + quote(clone().string()) + " && bash install.sh");
        if (r.exitCode != 0) built = "bash install.sh: " + r.all();
    }
    static void TearDownTestSuite() {
        delete dir;
        dir = nullptr;
    }
    void SetUp() override { ASSERT_TRUE(built.empty()) << built; }

    // The clone's raylab (built by the README's first command).
    static CommandResult student(const std::string& args) {
        return runCommand("cd " + quote(clone().string()) + " && " + kStudentRaylab + " " + args);
    }
};
ScratchDir* StudentRepo::dir = nullptr;
std::string StudentRepo::built;

// The ```sh lines of the doc-test: run blocks of README.md.
std::vector<std::string> readmeCommands(const fs::path& readme) {
    std::istringstream in(readFile(readme));
    std::vector<std::string> out;
    bool run = false, inside = false;
    for (std::string line; std::getline(in, line);) {
        if (inside) {
            if (line.rfind("```", 0) == 0) inside = false;
            else if (run && !line.empty()) out.push_back(line);
        } else if (line.rfind("```sh", 0) == 0) {
            inside = true;
        } else {
            run = line == "<!-- doc-test: run -->";
            continue;
        }
        if (!inside) run = false;
    }
    return out;
}

// The report without its first line (which names where the pictures come
// from: the solution rendered here, or the repository's references).
std::string report(const std::string& out) {
    // The header ("raylab check: stage 03-shadows, lab ... against ..."), not
    // a note on an earlier stage ("raylab check: stage f3 reads your own ...").
    std::smatch header;
    if (!std::regex_search(out, header, std::regex("raylab check: stage [^ ]+, [^\n]*\n")))
        return out;
    return header.prefix().str() + header.suffix().str();
}

}  // namespace

// The README's commands run in the clone, as written: the first builds
// the clone's raylab (a build from the clone alone; the suite's set-up ran it
// first), the last checks the lab as handed out, which fails until the
// TODOs are done.
TEST_F(StudentRepo, ItsReadmeCommandsBuildAndCheckAFreshClone) {
    const std::vector<std::string> commands = readmeCommands(clone() / "README.md");
    ASSERT_EQ(commands, (std::vector<std::string>{"bash install.sh", kStudentRaylab + " stages",
                                                  kStudentRaylab + " check --stage 01"}));
    for (const std::string& c : commands) {
        CommandResult r = runCommand("cd " + quote(clone().string()) + " && " + c);
        if (c.find("check") == std::string::npos) {
            ASSERT_EQ(r.exitCode, 0) << c << "\n" << r.all();
        } else {
            EXPECT_EQ(r.exitCode, 1) << r.all();
            EXPECT_NE(r.out.find("against course/references/01-raycast"), std::string::npos)
                << r.out;
            EXPECT_NE(r.err.find("open TODO"), std::string::npos) << r.err;
        }
        if (c == kStudentRaylab + " stages") {
            for (const char* stage : {"01-raycast", "02-shading", "03-shadows"})
                EXPECT_NE(r.out.find(stage), std::string::npos) << r.out;
            EXPECT_EQ(r.out.find("04-recursion"), std::string::npos) << r.out;
        }
    }
    EXPECT_TRUE(fs::is_regular_file(clone() / kStudentRaylab));
}

TEST_F(StudentRepo, HoldsNoAnswerAndTheSearchFindsPlantedOnes) {
    const std::string search = "node " +
                               quote((sourceDir() / "web/tests/answer_search.mjs").string()) +
                               " --student-repo ";
    CommandResult r = runCommand(search + quote(origin().string()));
    EXPECT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("0 findings"), std::string::npos) << r.out;
    for (const char* part :
         {"solution/01-raycast/intersect_sphere.glsl", "raytrace/reference", "src/bench",
          "fur_reference", "silhouette.cpp", "silhouette.h", "cmd_bench.cpp", "tests/"})
        for (const std::string& f : filesUnder(origin()))
            EXPECT_EQ(f.find(part), std::string::npos) << f << " holds " << part;

    // Three answers planted in a copy: a solution file, the reference
    // tracer's code, a check's reference put back; and a later stage's
    // texture.
    ScratchDir planted;
    const fs::path copy = planted / "repo";
    fs::copy(origin(), copy, fs::copy_options::recursive);
    fs::remove_all(copy / ".git");
    fs::copy_file(sourceDir() / "solution/02-shading/blinn_phong.glsl", copy / "labs/notes.glsl");
    fs::create_directories(copy / "assets/textures");
    fs::copy_file(sourceDir() / "assets/textures/earth.png", copy / "assets/textures/earth.png");
    fs::copy_file(sourceDir() / "framework/src/raytrace/reference/reference_intersect.cpp",
                  copy / "framework/src/core/notes.cpp");
    replaceInFile(copy / "framework/src/grading/checks/intersect_function_cases.cpp",
                  "RAYLAB_REFERENCE(s, nullptr);",
                  "RAYLAB_REFERENCE(s, [](const FunctionCase& c) { return c.in[0]; });");
    r = runCommand(search + quote(copy.string()));
    EXPECT_EQ(r.exitCode, 1) << r.all();
    for (const char* found :
         {"labs/notes.glsl: holds the solution region of solution/02-shading/blinn_phong.glsl",
          "framework/src/core/notes.cpp: holds the reference tracer's line",
          "intersect_function_cases.cpp: a reference or stand-in left in",
          "assets/textures/earth.png: an asset no released stage draws"})
        EXPECT_NE(r.out.find(found), std::string::npos) << found << "\n" << r.out;
}

TEST_F(StudentRepo, ChecksASolvedLabAsPassingAndTheHandedOutOneAsFailing) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    for (const char* stage : {"01", "02", "03"}) {
        CommandResult r =
            student("check --stage " + std::string(stage) + " --lab " + quote(lab.path()));
        EXPECT_EQ(r.exitCode, 0) << stage << ": " << r.all();
        EXPECT_NE(r.out.find("score: 100.00/100"), std::string::npos) << r.out;
        r = student("check --stage " + std::string(stage));
        EXPECT_EQ(r.exitCode, 1) << stage << ": " << r.all();
        EXPECT_NE(r.out.find("score: 0.00/100"), std::string::npos) << r.out;
    }
}

TEST_F(StudentRepo, GivesEachCatalogedMistakeTheInstructorsVerdict) {
    int mistakes = 0;
    for (const char* id : {"01-raycast", "02-shading", "03-shadows"}) {
        const raylab::StageInfo& stage = raylab::findStage(id);
        bool first = true;
        for (const raylab::CatalogMistake& m : raylab::stageMistakes(stage)) {
            SCOPED_TRACE(m.file.filename().string());
            ScratchDir lab;
            writeSolvedLabs(lab.path());
            for (const auto& [from, to] : m.replace)
                replaceInFile(lab / id / m.shaderFile, from, to);
            const std::string args =
                "check --stage " + std::string(id) + " --lab " + quote(lab.path());
            CommandResult r = student(args);
            EXPECT_EQ(r.exitCode, 1) << r.all();
            std::vector<std::string> failed = failedViews(r.out);
            std::sort(failed.begin(), failed.end());
            EXPECT_EQ(failed, m.caughtBy) << r.out;
            EXPECT_EQ(raylab::causesNamed(r.out, stage), m.hints) << r.out;
            if (first) {  // the instructors' report on the same pictures, word for word
                CommandResult theirs = runRaylab(
                    args + " --against " + quote((sourceDir() / "tests/reference" / id).string()));
                EXPECT_EQ(report(r.out), report(theirs.out));
                first = false;
            }
            ++mistakes;
        }
    }
    EXPECT_GE(mistakes, 15);
}

TEST_F(StudentRepo, RefusesWhatNeedsTheSolutionInOneLine) {
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"check --stage 01 --solution", "--solution: this is a student repository"},
        {"render --stage 01 --solution --out x.png", "--solution: this is a student repository"},
        {"render --stage 01 --reference --out x.png", "--reference: the CPU reference tracer"},
        {"demo --scene pro", "raylab demo draws the solution"},
        {"render --stage 01 --scene lite --out x.png",
         "--scene lite: assets/scenes/lite.json is not in this repository (it holds the scenes "
         "of the stages released so far: stage01.json, stage02.json, stage03-far.json)"},
        {"check --stage 04", "04"},
    };
    for (const auto& [args, why] : refused) {
        CommandResult r = student(args);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.all();
        EXPECT_NE(r.err.find(why), std::string::npos) << args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    }
    EXPECT_FALSE(fs::exists(clone() / "x.png"));
    // Nor do the guides send the student to them (their with-solution
    // blocks are left out: lab_folder.h), nor to the folders left out.
    int guides = 0;
    for (const std::string& f : filesUnder(origin() / "labs"))
        if (fs::path(f).filename() == "README.md") {
            const std::string text = readFile(origin() / "labs" / f);
            for (const char* absent :
                 {"--solution", "--reference", "raylab demo", "solution/", "with-solution"})
                EXPECT_EQ(text.find(absent), std::string::npos) << f << " says " << absent;
            ++guides;
        }
    EXPECT_GE(guides, 4);
    CommandResult help = student("--help");
    for (const char* absent : {"grade", "bench", "handout", "student-repo", "demo"})
        EXPECT_EQ(help.out.find("\n  " + std::string(absent) + " "), std::string::npos)
            << absent << "\n"
            << help.out;
    // Nor does a command's help offer stage 08's scenes, which it lacks.
    help = student("render --help");
    EXPECT_NE(help.out.find("--scene"), std::string::npos) << help.out;
    EXPECT_EQ(help.out.find("lite, pro"), std::string::npos) << help.out;
}

// Runs last (gtest keeps the file's order): it changes the clone.
TEST_F(StudentRepo, ALaterReleaseReachesTheCloneWithoutTouchingTheStudentsWork) {
    // The student's work, committed in the clone.
    const fs::path mine = clone() / "labs/01-raycast/intersect_sphere.glsl";
    const std::string work = readFile(mine) + "// my own note\n";
    writeFile(mine, work);
    CommandResult r =
        runCommand("cd " + quote(clone().string()) + " && " + kGit + "commit -qam 'My 01 so far'");
    ASSERT_EQ(r.exitCode, 0) << r.all();

    r = runRaylab("student-repo --stages 01-02 --out " + quote(origin().string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("already releases 03-shadows"), std::string::npos) << r.err;

    r = runRaylab("student-repo --stages 01-04,f1-f3 --out " + quote(origin().string()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("new labs 04-recursion"), std::string::npos) << r.out;
    r = runCommand("cd " + quote(origin().string()) + " && " + kGit + "add -A && " + kGit +
                   "commit -qm 'Stage 04' && git status --porcelain");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    // The release touched no lab folder of 01-03.
    r = runCommand("cd " + quote(origin().string()) + " && git diff --stat HEAD~1 -- labs/0[1-3]*");
    EXPECT_EQ(r.out, "") << r.all();

    r = runCommand("cd " + quote(clone().string()) + " && " + kGit + "pull -q --no-rebase");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_EQ(readFile(mine), work);
    EXPECT_TRUE(fs::is_regular_file(clone() / "labs/04-recursion/README.md"));
    EXPECT_TRUE(fs::is_directory(clone() / "course/references/04-recursion"));
    EXPECT_TRUE(fs::is_regular_file(clone() / "course/handed-out/04-recursion/front.png"));

    // f3's fin count, which the student build judges against the count
    // tables (it holds no silhouette test): the instructors' report on the
    // lab as handed out, word for word, and a pass on the solved one.
    CommandResult mineF3 = student("check --stage f3");
    EXPECT_EQ(mineF3.exitCode, 1) << mineF3.all();
    CommandResult theirs =
        runRaylab("check --stage f3 --lab " + quote((clone() / "labs").string()) + " --against " +
                  quote((sourceDir() / "tests/reference/f3-fins").string()));
    EXPECT_NE(mineF3.out.find("FAIL fin_count"), std::string::npos) << mineF3.out;
    // (Run from here, the instructors' build names the clone's lab folder
    // in full, which the student's, run in the clone, calls labs/.)
    std::string theirsHere = theirs.out;
    const std::string labs = (clone() / "labs").string();
    const std::vector<std::pair<std::string, std::string>> named = {{" --lab " + labs, ""},
                                                                    {labs + "/", "labs/"}};
    for (const auto& [from, to] : named)
        for (std::size_t at; (at = theirsHere.find(from)) != std::string::npos;)
            theirsHere.replace(at, from.size(), to);
    EXPECT_NE(mineF3.out.find("reads your own labs/f2-shells/"), std::string::npos)
        << "the earlier stages' slips, named where they are";
    EXPECT_EQ(report(mineF3.out), report(theirsHere));
    ScratchDir solved;
    writeSolvedLabs(solved.path());
    CommandResult solvedF3 = student("check --stage f3 --lab " + quote(solved.path()));
    EXPECT_EQ(solvedF3.exitCode, 0) << solvedF3.all();
    EXPECT_NE(solvedF3.out.find("PASS fin_count"), std::string::npos) << solvedF3.out;
}
