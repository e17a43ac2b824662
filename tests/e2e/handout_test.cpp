// `raylab handout`: the stages a course has released, for students. A stage
// folder holds its own files in lab form and reads the stages it builds on
// from the student's own folders, so no handout holds the solution of a stage
// it hands out; `check`, `run` and grading follow the same search path.
#include "lab_markers.h"
#include "stage_catalog.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

using namespace raylab::test;

namespace {

std::vector<std::string> topLevel(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string normalised(const std::string& line) {
    std::string out;
    std::istringstream words(line);
    for (std::string w; words >> w;) out += (out.empty() ? "" : " ") + w;
    return out;
}

// The code lines of every //@solution region of STAGE's own files and, at
// the open level, the code an open region's guided part gives (the guided
// level hands it out, the open level takes it away), as regions of their
// own; lines the open stub has too (a signature, a brace) left out.
std::vector<std::vector<std::string>> solutionRegions(const raylab::StageInfo& stage,
                                                      raylab::Level level) {
    std::vector<std::vector<std::string>> regions;
    for (const auto& e : fs::directory_iterator(stage.folder())) {
        if (e.path().filename() == "stage.json" || e.path().filename() == "guide.md") continue;
        std::istringstream in(readFile(e.path()));
        long region = -1, given = -1;  // indices in `regions`, -1: none
        bool inStub = false;
        std::set<std::string> stub;  // the open stub's lines
        for (std::string line; std::getline(in, line);) {
            const std::string l = normalised(line);
            if (l.rfind("//@solution", 0) == 0) {
                regions.emplace_back();
                region = long(regions.size()) - 1;
            } else if (l.rfind("//@stub", 0) == 0) {
                region = -1;
            } else if (l == "//@open") {
                inStub = true;
                stub.clear();
            } else if (l == "//@guided") {
                inStub = false;
                if (level == raylab::Level::Open) {
                    regions.emplace_back();
                    given = long(regions.size()) - 1;
                }
            } else if (l == "//@end-open") {
                given = -1;
            } else if (inStub) {
                if (l.rfind("//@ ", 0) == 0) stub.insert(normalised(l.substr(4)));
            } else if (!l.empty() && l.rfind("//", 0) != 0) {
                if (region >= 0) regions[std::size_t(region)].push_back(l);
                else if (given >= 0 && !stub.count(l)) regions[std::size_t(given)].push_back(l);
            }
        }
    }
    regions.erase(
        std::remove_if(regions.begin(), regions.end(), [](const auto& r) { return r.empty(); }),
        regions.end());
    return regions;
}

// Every file under DIR that holds one of REGIONS: all of its code lines, in
// order (other lines may come between them: a region copied with a line
// added is still the answer).
std::vector<std::string> filesWithARegion(const fs::path& dir,
                                          const std::vector<std::vector<std::string>>& regions) {
    std::vector<std::string> found;
    for (const std::string& f : filesUnder(dir)) {
        std::vector<std::string> lines;
        std::istringstream in(readFile(dir / f));
        for (std::string line; std::getline(in, line);) lines.push_back(normalised(line));
        for (const auto& region : regions) {
            std::size_t next = 0;
            for (const std::string& l : lines)
                if (next < region.size() && l == region[next]) ++next;
            if (next == region.size()) {
                found.push_back(f + ": " + region.front());
                break;
            }
        }
    }
    return found;
}

std::vector<std::vector<std::string>> regionsOf(const std::string& list,
                                                raylab::Level level = raylab::Level::Guided) {
    std::vector<std::vector<std::string>> all;
    std::istringstream in(list);
    for (std::string id; std::getline(in, id, ',');) {
        auto r = solutionRegions(raylab::findStage(id), level);
        all.insert(all.end(), r.begin(), r.end());
    }
    return all;
}

}  // namespace

// The README's own command, a trailing slash included, and into an empty folder.
TEST(Handout, WritesEachStagesOwnFilesAndTheyRunFromTheStudentsFolders) {
    ScratchDir dir;
    CommandResult r = runCommand("cd " + quote(dir.path()) + " && " + quote(raylabExe()) +
                                 " handout --stages 01-03 --out week3/");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const fs::path out = dir / "week3";
    EXPECT_EQ(topLevel(out),
              (std::vector<std::string>{"01-raycast", "02-shading", "03-shadows", "README.md"}));
    EXPECT_EQ(topLevel(out / "03-shadows"),
              (std::vector<std::string>{"README.md", "expected.png", "light_visibility.glsl",
                                        "unfinished.png"}))
        << "03 holds only the file it adds";
    EXPECT_EQ(readFile(out / "03-shadows" / "light_visibility.glsl"),
              readFile(sourceDir() / "labs/03-shadows/light_visibility.glsl"))
        << "in lab form, as labs/ has it";
    const std::string guide = readFile(out / "03-shadows" / "README.md");
    EXPECT_EQ(guide.find("provided, solved"), std::string::npos) << "a guide tells no untruth";
    EXPECT_NE(guide.find("`02-shading/` (`blinn_phong.glsl`"), std::string::npos) << guide;
    EXPECT_NE(readFile(out / "README.md").find("keep every stage folder"), std::string::npos);
    // The guide's commands run the student's handout, not the project's labs/
    // (the guides' own text: "<build folder>/raylab check ...").
    const std::string guide02 = readFile(out / "02-shading" / "README.md");
    EXPECT_NE(guide02.find("/raylab check --stage 02 --lab week3/"), std::string::npos);
    EXPECT_EQ(guide02.find("/raylab check --stage 02\n"), std::string::npos) << guide02;
    EXPECT_NE(guide02.find("/raylab run --stage 02 --solution"), std::string::npos)
        << "the solution's command stays as it is";

    // Every stage it holds checks (runs, and fails on its open TODOs), and a
    // fix in 01 shows in 03.
    for (const char* stage : {"01", "02", "03"}) {
        CommandResult c = runRaylab(std::string("check --stage ") + stage + " --lab " + quote(out));
        EXPECT_EQ(c.exitCode, 1) << stage << ": " << c.all();
    }
    ScratchDir solved;
    writeSolvedLabs(solved.path());
    CommandResult before = runRaylab("render --stage 03 --lab " + quote(out) +
                                     " --size 32x24 --out " + quote(dir / "before.png"));
    ASSERT_EQ(before.exitCode, 0) << before.all();
    for (const char* f : {"intersect_sphere.glsl", "find_closest.glsl"})
        fs::copy_file(solved / "01-raycast" / f, out / "01-raycast" / f,
                      fs::copy_options::overwrite_existing);
    CommandResult after = runRaylab("render --stage 03 --lab " + quote(out) +
                                    " --size 32x24 --out " + quote(dir / "after.png"));
    ASSERT_EQ(after.exitCode, 0) << after.all();
    EXPECT_NE(readFile(dir / "before.png"), readFile(dir / "after.png"))
        << "stage 03 runs the student's own 01";
    // Every stage solved in the student's folders: every check passes.
    for (const char* stage : {"02-shading", "03-shadows"})
        for (const auto& e : fs::directory_iterator(out / stage))
            if (e.path().extension() == ".glsl" || e.path().extension() == ".frag")
                fs::copy_file(solved / stage / e.path().filename(), e.path(),
                              fs::copy_options::overwrite_existing);
    for (const char* stage : {"01", "02", "03"}) {
        CommandResult c = runRaylab(std::string("check --stage ") + stage + " --lab " + quote(out));
        EXPECT_EQ(c.exitCode, 0) << stage << ": " << c.all();
    }

    // An existing empty folder is fine too.
    fs::create_directories(dir / "fur");
    CommandResult fur = runRaylab("handout --stages f1,f2 --out " + quote(dir / "fur/"));
    ASSERT_EQ(fur.exitCode, 0) << fur.all();
    EXPECT_FALSE(fs::exists(dir / "fur" / "f2-shells" / "normal_matrix.glsl"))
        << "f1's solved files are not in f2's folder";
    EXPECT_FALSE(fs::exists(dir / "fur" / "f3-fins"));
}

// The scan: no handout holds a //@solution region of a stage it hands out.
// It finds them where they are (labs/ as a whole holds every earlier answer).
TEST(Handout, NoHandoutHoldsASolutionOfAStageItHandsOut) {
    ScratchDir dir;
    const std::vector<std::string> releases = {"01-03", "f1,f2", "01-08", "f1-f4", "03,05", "04"};
    int n = 0;
    for (const std::string& release : releases)
        for (const char* carry : {"own", "solved"}) {
            const fs::path out = dir / ("h" + std::to_string(n++));
            CommandResult r = runRaylab("handout --stages " + release + " --carry " + carry +
                                        " --out " + quote(out));
            ASSERT_EQ(r.exitCode, 0) << r.all();
            std::string ids;
            for (const std::string& stage : topLevel(out))
                if (stage != "README.md") ids += (ids.empty() ? "" : ",") + stage;
            EXPECT_EQ(filesWithARegion(out, regionsOf(ids)), std::vector<std::string>{})
                << "--stages " << release << " --carry " << carry;
        }
    // The control: labs/ whole, read as a handout of every stage.
    std::string all;
    for (const raylab::StageInfo& s : raylab::allStages()) all += (all.empty() ? "" : ",") + s.id;
    EXPECT_GT(filesWithARegion(sourceDir() / "labs", regionsOf(all)).size(), 10u);
}

// A course that hands out 03 after 01 and 02's deadlines, their solutions with it.
TEST(Handout, CarrySolvedKeepsAStageFolderWhole) {
    ScratchDir dir;
    CommandResult r = runRaylab("handout --stages 03 --carry solved --out " + quote(dir / "week5"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_TRUE(fs::exists(dir / "week5/03-shadows/blinn_phong.glsl"));
    EXPECT_NE(readFile(dir / "week5/03-shadows/README.md").find("provided, solved"),
              std::string::npos);
    CommandResult c = runRaylab("check --stage 03 --lab " + quote(dir / "week5"));
    EXPECT_EQ(c.exitCode, 1) << "it runs on its own (its TODOs fail): " << c.all();

    // Without --carry solved the folder needs the student's 01 and 02 beside it.
    ASSERT_EQ(runRaylab("handout --stages 03 --out " + quote(dir / "alone")).exitCode, 0);
    CommandResult missing = runRaylab("check --stage 03 --lab " + quote(dir / "alone"));
    EXPECT_EQ(missing.exitCode, 2) << missing.all();
    EXPECT_NE(missing.err.find("03-shadows builds on your own 02-shading/, 01-raycast/"),
              std::string::npos)
        << missing.err;
}

TEST(Handout, BadRequestsWriteNothing) {
    ScratchDir dir;
    writeFile(dir / "taken" / "notes.txt", "mine");
    const struct {
        std::string args;
        const char* expected;
    } cases[] = {
        {"--stages 01-f2 --out " + quote(dir / "a"), "different tracks"},
        {"--stages 03-01 --out " + quote(dir / "b"), "comes after"},
        {"--stages 42 --out " + quote(dir / "c"), "unknown stage"},
        {"--stages 01 --out " + quote(dir / "taken"), "not an empty folder"},
        {"--stages 01 --out " + quote(dir / "d") + " --labs " + quote(dir / "nolabs"),
         "does not exist"},
        {"--stages 01 --carry some --out " + quote(dir / "e"), "--carry must be own"},
        {"--stages 01 --level expert --out " + quote(dir / "g"), "unknown level 'expert'"},
        {"--stages 01 --out " + quote(dir / "f") + " --course " + quote(dir / "none.json"),
         "cannot read"},
    };
    for (const auto& c : cases) {
        CommandResult r = runRaylab("handout " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.all();
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    }
    EXPECT_EQ(topLevel(dir.path()), std::vector<std::string>{"taken"});
    EXPECT_EQ(readFile(dir / "taken" / "notes.txt"), "mine");
}

// A course file's weights reach the guides the students read.
TEST(Handout, TheGuidesShowTheCoursesWeights) {
    ScratchDir dir;
    writeFile(dir / "course.json", R"({"stages": {"03": {"grading": {"views": 20}}}})");
    CommandResult r = runRaylab("handout --stages 03 --course " + quote(dir / "course.json") +
                                " --out " + quote(dir / "out"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const std::string guide = readFile(dir / "out/03-shadows/README.md");
    EXPECT_NE(guide.find("**Images, 20 points**"), std::string::npos) << guide;
    EXPECT_NE(guide.find("`lightVisible` 80"), std::string::npos);
    EXPECT_EQ(guide.find("**Deadline:**"), std::string::npos) << "the course set none";
    EXPECT_NE(guide.find("**Earlier stages:** this stage is graded with the stages it builds on "
                         "solved"),
              std::string::npos);
}

// A course file's deadlines and late policy reach the guides too, each
// stage's own deadline where it has one; and its rule on earlier stages.
TEST(Handout, TheGuidesShowTheCoursesDeadlinesAndLatePolicy) {
    ScratchDir dir;
    writeFile(dir / "course.json", R"({"earlier_stages": "own", "late": {
        "deadline": "2026-12-10T23:59:00+01:00",
        "deadlines": {"02-shading": "2026-12-17T23:59:00+01:00"},
        "grace_minutes": 15, "penalty_per_day": 10, "max_penalty": 50}})");
    CommandResult r = runRaylab("handout --stages 01-02 --course " + quote(dir / "course.json") +
                                " --out " + quote(dir / "out"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const std::string g01 = readFile(dir / "out/01-raycast/README.md");
    const std::string g02 = readFile(dir / "out/02-shading/README.md");
    EXPECT_NE(g01.find("**Deadline:** 2026-12-10 22:59 UTC. Work handed in later loses 10% of the "
                       "score it earned for every day or part of a day past it (after 15 "
                       "minutes' grace), at most 50%."),
              std::string::npos)
        << g01;
    EXPECT_NE(g02.find("**Deadline:** 2026-12-17 22:59 UTC."), std::string::npos) << g02;
    EXPECT_EQ(g01.find("**Earlier stages:**"), std::string::npos) << "01 builds on none";
    EXPECT_NE(g02.find("**Earlier stages:** this stage is graded with your own earlier stages"),
              std::string::npos);
}

// The open level (`--level open`): whole functions from their contracts.
// Every stage of both tracks hands out, its untouched lab fails its checks,
// the lab solved passes them, and no handout holds the code that level
// takes away (the guided level's given code of an open region included).
TEST(Handout, TheOpenLevelHandsOutEveryStageWithoutItsAnswers) {
    ScratchDir dir;
    for (const char* release : {"01-08", "f1-f4"}) {
        const fs::path out = dir / (std::string("open-") + release);
        CommandResult r = runRaylab(std::string("handout --level open --stages ") + release +
                                    " --out " + quote(out));
        ASSERT_EQ(r.exitCode, 0) << r.all();
        EXPECT_NE(r.out.find("at the open level"), std::string::npos) << r.out;
        std::string ids;
        for (const std::string& stage : topLevel(out))
            if (stage != "README.md") ids += (ids.empty() ? "" : ",") + stage;
        EXPECT_EQ(filesWithARegion(out, regionsOf(ids, raylab::Level::Open)),
                  std::vector<std::string>{})
            << release;
        for (const std::string& stage : topLevel(out)) {
            if (stage == "README.md") continue;
            CommandResult c =
                runRaylab("check --stage " + stage + " --lab " + quote(out) + " --size 64x48");
            EXPECT_EQ(c.exitCode, 1) << stage << " as handed out: " << c.all();
            // The open lab's own "Before you start" picture, under the guided one's name.
            EXPECT_EQ(readFile(out / stage / "unfinished.png"),
                      readFile(sourceDir() / "labs" / stage / "unfinished-open.png"))
                << stage;
            EXPECT_FALSE(fs::exists(out / stage / "unfinished-open.png")) << stage;
        }
    }
    // The control: a guided handout holds the open level's answers (its given code).
    const fs::path guided = dir / "guided";
    ASSERT_EQ(runRaylab("handout --stages 04 --out " + quote(guided)).exitCode, 0);
    EXPECT_FALSE(filesWithARegion(guided, regionsOf("04-recursion", raylab::Level::Open)).empty());

    // The open lab solved: every check passes, and a helper function of the
    // student's own (not in the handed-out file) breaks neither the program
    // nor the function checks' harness.
    const fs::path out = dir / "open-01-08";
    ScratchDir solved;
    writeSolvedLabs(solved.path());
    for (const char* stage : {"01-raycast", "02-shading", "03-shadows", "04-recursion"})
        for (const auto& e : fs::directory_iterator(out / stage))
            if (e.path().extension() == ".glsl" || e.path().extension() == ".frag")
                fs::copy_file(solved / stage / e.path().filename(), e.path(),
                              fs::copy_options::overwrite_existing);
    writeFile(out / "01-raycast" / "intersect_sphere.glsl",
              "// A student's own version, with a helper of their own.\n"
              "float nearestRootInFront(float q, float c)\n"
              "{\n"
              "    float t0 = min(c / q, q), t1 = max(c / q, q);\n"
              "    return t0 > T_MIN ? t0 : (t1 > T_MIN ? t1 : NO_HIT);\n"
              "}\n\n"
              "float intersectSphere(Ray ray, vec3 center, float radius)\n"
              "{\n"
              "    vec3 oc = ray.origin - center;\n"
              "    float b = dot(oc, ray.dir);\n"
              "    vec3 closest = oc - b * ray.dir;\n"
              "    float h = radius * radius - dot(closest, closest);\n"
              "    if (h < 0.0) return NO_HIT;\n"
              "    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(h);\n"
              "    if (q == 0.0) return NO_HIT;\n"
              "    return nearestRootInFront(q, dot(oc, oc) - radius * radius);\n"
              "}\n");
    for (const char* stage : {"01", "02", "03", "04"}) {
        CommandResult c = runRaylab(std::string("check --stage ") + stage + " --lab " + quote(out));
        EXPECT_EQ(c.exitCode, 0) << stage << " solved: " << c.all();
    }
}

// f3's guide, as a handout hands it out, run from the student's own folder
// (not the RayLab folder): its render, check and shader commands work as
// written (only the guide's binary, "<build folder>/raylab", is this build's,
// and renders are small). A scene path not found there is the project's.
TEST(Handout, TheF3GuidesCommandsRunFromTheStudentsFolder) {
    ScratchDir dir;
    ASSERT_EQ(runCommand("cd " + quote(dir.path()) + " && " + quote(raylabExe()) +
                         " handout --stages f1-f3 --out fur/")
                  .exitCode,
              0);
    std::istringstream guide(readFile(dir / "fur" / "f3-fins" / "README.md"));
    int ran = 0;
    bool shader = false, scene = false;
    // A command line of the guide: its binary (any folder), then the command.
    const std::regex binary(R"(^\S*/raylab (.*)$)");
    for (std::string line; std::getline(guide, line);) {
        std::smatch m;
        if (!std::regex_match(line, m, binary)) continue;
        std::string command = m[1];
        command = command.substr(0, command.find('#'));
        const bool render = command.rfind("render ", 0) == 0;
        if (!render && command.rfind("check ", 0) != 0 && command.rfind("shader ", 0) != 0)
            continue;  // run opens a window
        if (command.find("--solution") != std::string::npos) continue;
        if (render) command += " --size 40x30";
        CommandResult r =
            runCommand("cd " + quote(dir.path()) + " && " + quote(raylabExe()) + " " + command);
        // check fails on the lab's open TODOs (1), but runs; nothing else may fail.
        EXPECT_LE(r.exitCode, command.rfind("check ", 0) == 0 ? 1 : 0) << command << "\n"
                                                                       << r.all();
        EXPECT_EQ(r.err.find("does not exist"), std::string::npos) << command << "\n" << r.err;
        shader = shader || (command.rfind("shader ", 0) == 0 &&
                            r.out.find("uFurLength") != std::string::npos);
        scene = scene || command.find("assets/scenes/fur/coarse.json") != std::string::npos;
        ++ran;
    }
    EXPECT_GE(ran, 6);
    EXPECT_TRUE(shader) << "the guide names raylab shader, and it prints the fins' program";
    EXPECT_TRUE(scene) << "the guide's command with a project scene ran";
    EXPECT_TRUE(fs::exists(dir / "coarse.png"));
    // A scene that is nowhere is still a one-line error.
    CommandResult missing = runCommand("cd " + quote(dir.path()) + " && " + quote(raylabExe()) +
                                       " render --stage f3 --lab fur/ --scene assets/scenes/fur/"
                                       "nope.json --out nope.png");
    EXPECT_EQ(missing.exitCode, 2) << missing.all();
    EXPECT_FALSE(fs::exists(dir / "nope.png"));
}
