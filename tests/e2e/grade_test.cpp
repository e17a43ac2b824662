// `raylab grade` on small classes: output files, determinism, the seed, bad
// arguments. (The class of 30 with every broken case is grade_class_test.cpp.)
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <regex>

using namespace raylab::test;

namespace {

// A class of two: a solved copy of the labs and the untouched labs, with
// stage 02 missing from the second.
void makeClass(const fs::path& dir) {
    writeSolvedLabs(dir / "ada");
    fs::copy(sourceDir() / "labs", dir / "bob", fs::copy_options::recursive);
    fs::remove_all(dir / "bob" / "02-shading");
}

}  // namespace

TEST(Grade, WritesEveryReportAndGivesTheSameScoresTwice) {
    ScratchDir dir;
    makeClass(dir / "class");
    const std::string args = "grade --submissions " + quote((dir / "class").string()) +
                             " --stages 01,02 --jobs 2 --seed 11 --out ";
    CommandResult first = runRaylab(args + quote((dir / "a").string()));
    ASSERT_EQ(first.exitCode, 0) << first.all();
    CommandResult second = runRaylab(args + quote((dir / "b").string()));
    ASSERT_EQ(second.exitCode, 0) << second.all();

    for (const char* f : {"report.html", "summary.csv", "junit.xml", "students/ada/results.json",
                          "students/bob/results.json"})
        EXPECT_TRUE(fs::exists(dir / "a" / f)) << f;
    EXPECT_EQ(readFile(dir / "a" / "summary.csv"), readFile(dir / "b" / "summary.csv"))
        << "grading must be deterministic";
    auto ada = nlohmann::json::parse(readFile(dir / "a" / "students" / "ada" / "results.json"));
    EXPECT_DOUBLE_EQ(ada["score"].get<double>(), 200.0);
    auto bob = nlohmann::json::parse(readFile(dir / "a" / "students" / "bob" / "results.json"));
    EXPECT_LT(bob["score"].get<double>(), 10.0);
    EXPECT_NE(readFile(dir / "a" / "summary.csv").find("02-shading: not submitted"),
              std::string::npos);
    // The seeded views exist and are graded like the others.
    EXPECT_TRUE(fs::exists(dir / "a" / "students" / "ada" / "01-raycast" / "seeded-1.png"));
    EXPECT_TRUE(fs::exists(dir / "a" / "reference" / "01-raycast" / "seeded-3.png"));
    // No temporary files anywhere.
    for (const auto& e : fs::recursive_directory_iterator(dir / "a"))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(Grade, AnotherSeedGivesOtherViews) {
    ScratchDir dir;
    writeSolvedLabs(dir / "class" / "ada");
    for (const char* seed : {"1", "2"}) {
        CommandResult r =
            runRaylab("grade --submissions " + quote((dir / "class").string()) +
                      " --stages 01 --seed " + seed + " --out " + quote((dir / seed).string()));
        ASSERT_EQ(r.exitCode, 0) << r.all();
    }
    EXPECT_NE(readFile(dir / "1" / "reference" / "01-raycast" / "seeded-1.png"),
              readFile(dir / "2" / "reference" / "01-raycast" / "seeded-1.png"));
    EXPECT_EQ(readFile(dir / "1" / "reference" / "01-raycast" / "front.png"),
              readFile(dir / "2" / "reference" / "01-raycast" / "front.png"));
}

TEST(Grade, BadArgumentsAreOneLineErrors) {
    ScratchDir dir;
    fs::create_directories(dir / "empty");
    writeSolvedLabs(dir / "class" / "ada");
    const std::string cls = " --submissions " + quote((dir / "class").string()) + " --out " +
                            quote((dir / "out").string());
    struct Case {
        std::string args, expected;
    } cases[] = {
        {"grade --submissions /nonexistent --out " + quote((dir / "o").string()),
         "--submissions '/nonexistent': no such folder"},
        {"grade --submissions " + quote((dir / "empty").string()) + " --out " +
             quote((dir / "o").string()),
         "no student folders"},
        {"grade" + cls + " --stages 01,42", "unknown stage '42'"},
        {"grade" + cls + " --jobs 0", "--jobs must be between 1 and 64"},
        {"grade" + cls + " --timeout -1", "--timeout must be between"},
        {"grade" + cls + " --memory-mb 5", "--memory-mb must be 0"},
        {"grade --submissions " + quote((dir / "class").string()) + " --out " +
             quote((dir / "class" / "graded").string()),
         "must be separate folders"},
        {"grade --submissions " + quote((dir / "class").string()) + " --out " +
             quote((dir / "class").string()),
         "must be separate folders"},
    };
    for (const Case& c : cases) {
        CommandResult r = runRaylab(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.all();
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

// Folder names that collide with the class files, an empty submission, a
// stage folder that is a link to the solution, and leftovers of an earlier
// run: none of them may touch another student's score or the report.
TEST(Grade, AwkwardFoldersAndAnEarlierRunChangeNothingForOthers) {
    ScratchDir dir;
    const fs::path cls = dir / "class";
    writeSolvedLabs(cls / "ada");
    writeSolvedLabs(cls / "reference");
    writeSolvedLabs(cls / "report.html");
    fs::create_directories(cls / "empty");
    fs::create_directories(cls / "linker");
    fs::create_directory_symlink(sourceDir() / "solution" / "01-raycast",
                                 cls / "linker" / "01-raycast");
    fs::create_directory_symlink(cls / "ada", cls / "alias");
    // Leftovers of an earlier run in --out.
    fs::create_directories(dir / "out" / "students" / "ada" / "01-raycast");
    writeFile(dir / "out" / "students" / "ada" / "01-raycast" / "result.json", "stale");
    writeFile(dir / "out" / "summary.csv", "stale");

    CommandResult r = runRaylab("grade --submissions " + quote(cls.string()) +
                                " --stages 01 --out " + quote((dir / "out").string()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.err.find("skipping alias: a symbolic link"), std::string::npos) << r.err;
    const std::string csv = readFile(dir / "out" / "summary.csv");
    EXPECT_NE(csv.find("ada,,100,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("reference,,100,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("report.html,,100,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("empty,,,0,"), std::string::npos) << "not submitted: empty" << csv;
    EXPECT_NE(csv.find("linker,,0,"), std::string::npos)
        << "a stage folder linked to the solution earns nothing\n"
        << csv;
    EXPECT_NE(csv.find("01-raycast: error"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("alias"), std::string::npos) << csv;
    EXPECT_TRUE(fs::is_regular_file(dir / "out" / "report.html"));
    EXPECT_TRUE(fs::exists(dir / "out" / "students" / "empty" / "results.json"));
}

// `raylab check` reads frames as grading does: a NaN fails the view and says so.
TEST(Grade, CheckSeesNaNLikeGrading) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    replaceInFile(lab / "02-shading" / "blinn_phong.glsl", "color += m.ambient;",
                  "color += m.ambient * sqrt(-1.0 - m.ambient.x);");
    CommandResult r = runRaylab("check --stage 02 --lab " + quote(lab.path().string()));
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_NE(r.out.find("pixels are NaN or Inf"), std::string::npos) << r.out;
}

// Ctrl-C during grading stops every child (looked for by its command line;
// the [g] keeps pgrep from finding the shell that runs it) (they run in process groups of
// their own, which the terminal's signal does not reach) and writes no
// report that would look complete.
TEST(Grade, InterruptStopsTheChildrenAndWritesNoReport) {
    ScratchDir dir;
    writeSolvedLabs(dir / "class" / "looper");
    auto spec =
        nlohmann::json::parse(readFile(sourceDir() / "tests/grading/broken/endless-loop.json"));
    replaceInFile(dir / "class" / "looper" / spec["stage"].get<std::string>() /
                      spec["file"].get<std::string>(),
                  spec["replace"][0][0], spec["replace"][0][1]);
    const fs::path out = dir / "out-interrupted";
    CommandResult r =
        runCommand(quote(RAYLAB_EXE) + " grade --submissions " + quote((dir / "class").string()) +
                   " --stages 02 --timeout 120 --out " + quote(out.string()) +
                   " & pid=$!; sleep 4; kill -INT $pid; wait $pid; echo \"rc=$?\"; sleep 1; " +
                   "echo \"left=$(pgrep -f '[g]rade-item --stage 02-shading --lab " +
                   (dir / "class" / "looper").string() + "' | wc -l)\"");
    EXPECT_NE(r.out.find("rc=130"), std::string::npos) << r.all();
    EXPECT_NE(r.out.find("left=0"), std::string::npos)
        << "children outlived the interrupted grader\n"
        << r.all();
    EXPECT_NE(r.err.find("interrupted; no report was written"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out / "report.html"));
    EXPECT_FALSE(fs::exists(out / "summary.csv"));
}

namespace {

// TEXT without the run's timings: JUnit time="...", Gradescope's
// execution_time, the HTML report's durations.
std::string withoutTimings(std::string text) {
    text = std::regex_replace(text, std::regex(R"(time="[0-9.]+")"), "time=\"\"");
    text = std::regex_replace(text, std::regex(R"("execution_time": *[0-9]+)"),
                              "\"execution_time\": 0");
    text = std::regex_replace(text, std::regex(R"(<span class="muted">[^<]*</span>)"), "<span/>");
    text = std::regex_replace(text, std::regex(R"(wall time <b>[^<]*</b>)"), "wall time");
    return text;
}

}  // namespace

// --shard K/N on every share, then --merge: the report an unsharded run
// writes, file for file (timings aside).
TEST(Grade, ShardsMergeIntoTheUnshardedReport) {
    ScratchDir dir;
    makeClass(dir / "class");
    fs::copy(sourceDir() / "labs", dir / "class" / "cy", fs::copy_options::recursive);
    const std::string args =
        "grade --submissions " + quote(dir / "class") + " --stages 01,02 --jobs 2 --seed 5 --out ";
    CommandResult whole = runRaylab(args + quote(dir / "whole"));
    ASSERT_EQ(whole.exitCode, 0) << whole.all();
    for (int k = 0; k < 2; ++k) {
        CommandResult share = runRaylab(args + quote(dir / ("s" + std::to_string(k))) +
                                        " --shard " + std::to_string(k) + "/2");
        ASSERT_EQ(share.exitCode, 0) << share.all();
        EXPECT_TRUE(fs::exists(dir / ("s" + std::to_string(k)) / "shard.json"));
        EXPECT_FALSE(fs::exists(dir / ("s" + std::to_string(k)) / "report.html"));
    }
    // Share 0 of 2 holds the 1st and 3rd student, share 1 the 2nd.
    EXPECT_TRUE(fs::exists(dir / "s0" / "students" / "ada"));
    EXPECT_TRUE(fs::exists(dir / "s0" / "students" / "cy"));
    EXPECT_TRUE(fs::exists(dir / "s1" / "students" / "bob"));
    EXPECT_FALSE(fs::exists(dir / "s1" / "students" / "ada"));

    CommandResult merge = runRaylab("grade --merge " + quote(dir / "merged") + " " +
                                    quote(dir / "s1") + " " + quote(dir / "s0"));
    ASSERT_EQ(merge.exitCode, 0) << merge.all();
    EXPECT_EQ(filesUnder(dir / "merged"), filesUnder(dir / "whole"));
    for (const char* f : {"summary.csv", "junit.xml", "report.html", "students/ada/results.json",
                          "students/bob/results.json", "students/cy/results.json"})
        EXPECT_EQ(withoutTimings(readFile(dir / "merged" / f)),
                  withoutTimings(readFile(dir / "whole" / f)))
            << f;
}

TEST(Grade, AMergeOfTheWrongSharesIsRefused) {
    ScratchDir dir;
    makeClass(dir / "class");
    const std::string args =
        "grade --submissions " + quote(dir / "class") + " --stages 01 --jobs 2 --out ";
    ASSERT_EQ(runRaylab(args + quote(dir / "s0") + " --shard 0/2 --seed 1").exitCode, 0);
    ASSERT_EQ(runRaylab(args + quote(dir / "s1") + " --shard 1/2 --seed 1").exitCode, 0);
    ASSERT_EQ(runRaylab(args + quote(dir / "t1") + " --shard 1/2 --seed 2").exitCode, 0);
    const struct {
        std::string args;
        const char* expected;
    } cases[] = {
        {quote(dir / "m") + " " + quote(dir / "s0"), "shares 1 of 2 are missing"},
        {quote(dir / "m") + " " + quote(dir / "s0") + " " + quote(dir / "s0"), "given twice"},
        {quote(dir / "m") + " " + quote(dir / "s0") + " " + quote(dir / "t1"), "another run"},
        {quote(dir / "m") + " " + quote(dir / "class"), "no shard.json"},
    };
    for (const auto& c : cases) {
        CommandResult r = runRaylab("grade --merge " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.all();
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "m" / "report.html"));
    }
    for (const char* bad : {"2/2", "1", "a/b", "0/0", "-1/2"}) {
        CommandResult r = runRaylab(args + quote(dir / "x") + " --shard " + bad);
        EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r.all();
        EXPECT_NE(r.err.find("expected K/N"), std::string::npos) << r.err;
    }
}

// An untouched lab earns nothing for its stage, also from views it already
// draws right (they never reach the stage's code); a solved lab earns all.
TEST(Grade, AnUntouchedLabScoresZero) {
    ScratchDir dir;
    makeClass(dir / "class");
    CommandResult r = runRaylab("grade --submissions " + quote(dir / "class") +
                                " --stages 03,07 --jobs 2 --seed 2 --out " + quote(dir / "out"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    auto bob = nlohmann::json::parse(readFile(dir / "out" / "students" / "bob" / "results.json"));
    EXPECT_DOUBLE_EQ(bob["score"].get<double>(), 0.0) << bob.dump(1);
    bool offView = false;
    for (const auto& t : bob["tests"])
        if (t["name"] == "03-shadows / shadows-off") {
            offView = true;
            EXPECT_NE(t["output"].get<std::string>().find("does not reach the stage's code"),
                      std::string::npos)
                << t.dump();
        }
    EXPECT_TRUE(offView);
    auto ada = nlohmann::json::parse(readFile(dir / "out" / "students" / "ada" / "results.json"));
    EXPECT_DOUBLE_EQ(ada["score"].get<double>(), 200.0);
    EXPECT_TRUE(fs::exists(dir / "out" / "reference" / "03-shadows" / "untouched" / "front.png"));
}

// At the open level (`--level open`) the lab as handed out is the open
// lab: its untouched pictures are the open stubs' (not the guided lab's),
// an untouched open lab earns nothing, a solved one everything.
TEST(Grade, AtTheOpenLevelTheOpenLabIsTheLabAsHandedOut) {
    ScratchDir dir;
    writeSolvedLabs(dir / "class" / "ada");
    ASSERT_EQ(runLabgen("--level open --labs " + quote(dir / "class" / "olga")).exitCode, 0);
    for (const char* level : {"guided", "open"}) {
        const fs::path out = dir / (std::string("out-") + level);
        CommandResult r =
            runRaylab("grade --submissions " + quote(dir / "class") +
                      " --stages 04 --seed 3 --level " + level + " --out " + quote(out));
        ASSERT_EQ(r.exitCode, 0) << r.all();
        auto olga = nlohmann::json::parse(readFile(out / "students" / "olga" / "results.json"));
        EXPECT_DOUBLE_EQ(olga["score"].get<double>(), 0.0) << level << olga.dump(1);
        auto ada = nlohmann::json::parse(readFile(out / "students" / "ada" / "results.json"));
        EXPECT_DOUBLE_EQ(ada["score"].get<double>(), 100.0) << level;
    }
    // The guided stub draws the first hit (glass as a mirror), the open one nothing.
    const std::string untouched = "reference/04-recursion/untouched/front.png";
    EXPECT_NE(readFile(dir / "out-guided" / untouched), readFile(dir / "out-open" / untouched));
    EXPECT_EQ(readFile(dir / "out-open" / untouched),
              readFile(dir / "out-open" / "students" / "olga" / "04-recursion" / "front.png"))
        << "olga's picture is the lab as handed out";
    CommandResult bad = runRaylab("grade --submissions " + quote(dir / "class") +
                                  " --stages 04 --level expert --out " + quote(dir / "x"));
    EXPECT_EQ(bad.exitCode, 2) << bad.all();
    EXPECT_NE(bad.err.find("unknown level 'expert'"), std::string::npos) << bad.err;
}

namespace {

// STUDENT's result for STAGE (students/<student>/<stage>/result.json).
nlohmann::json stageResult(const fs::path& out, const std::string& student,
                           const std::string& stage) {
    return nlohmann::json::parse(readFile(out / "students" / student / stage / "result.json"));
}

// A handout of 01-03 (each stage reads the student's own earlier folders),
// every file solved, then 01's findClosest keeping the first hit.
void handoutWithA01Slip(const fs::path& student) {
    fs::create_directories(student.parent_path());
    ASSERT_EQ(runRaylab("handout --stages 01-03 --out " + quote(student)).exitCode, 0);
    ScratchDir solved;
    writeSolvedLabs(solved.path());
    for (const char* stage : {"01-raycast", "02-shading", "03-shadows"})
        for (const auto& e : fs::directory_iterator(student / stage))
            if (e.path().extension() == ".glsl" || e.path().extension() == ".frag")
                fs::copy_file(solved / stage / e.path().filename(), e.path(),
                              fs::copy_options::overwrite_existing);
    replaceInFile(student / "01-raycast" / "find_closest.glsl", "if (t != NO_HIT && t < hit.t)",
                  "if (t != NO_HIT && hit.id < 0)");
}

}  // namespace

// A slip in 01 costs in 01 only: 02 and 03 of a handout read the student's
// own 01, but grading takes the earlier stages solved (the default), and
// names the student's 01 file where a later stage reads it. A course that
// chooses the student's own earlier stages pays the slip again.
TEST(Grade, AMistakeInAnEarlierStageCostsInItsOwnStageOnly) {
    ScratchDir dir;
    handoutWithA01Slip(dir / "class" / "ann");
    const std::string args =
        "grade --submissions " + quote(dir / "class") + " --stages 01-03 --jobs 2 --seed 5 --out ";
    CommandResult r = runRaylab(args + quote(dir / "out"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_LT(stageResult(dir / "out", "ann", "01-raycast")["score"].get<double>(), 80.0);
    for (const char* later : {"02-shading", "03-shadows"}) {
        const nlohmann::json s = stageResult(dir / "out", "ann", later);
        EXPECT_DOUBLE_EQ(s["score"].get<double>(), 100.0) << later << s.dump(1);
        const std::string message = s["message"].get<std::string>();
        EXPECT_NE(message.find("01-raycast/find_closest.glsl (findClosest"), std::string::npos)
            << later << ": " << message;
        EXPECT_NE(message.find("graded with the earlier stages solved"), std::string::npos);
    }
    EXPECT_NE(readFile(dir / "out/students/ann/report.html").find("01-raycast/find_closest.glsl"),
              std::string::npos);

    writeFile(dir / "own.json", R"({"earlier_stages": "own"})");
    CommandResult own =
        runRaylab(args + quote(dir / "own") + " --course " + quote(dir / "own.json"));
    ASSERT_EQ(own.exitCode, 0) << own.all();
    std::printf("[ figure   ] the 01 slip, seed 5: 01 %.2f; earlier stages solved: 02 %.2f, 03 "
                "%.2f; own: 02 %.2f, 03 %.2f (docs/grading.md)\n",
                stageResult(dir / "out", "ann", "01-raycast")["score"].get<double>(),
                stageResult(dir / "out", "ann", "02-shading")["score"].get<double>(),
                stageResult(dir / "out", "ann", "03-shadows")["score"].get<double>(),
                stageResult(dir / "own", "ann", "02-shading")["score"].get<double>(),
                stageResult(dir / "own", "ann", "03-shadows")["score"].get<double>());
    for (const char* later : {"02-shading", "03-shadows"}) {
        const nlohmann::json s = stageResult(dir / "own", "ann", later);
        EXPECT_LT(s["score"].get<double>(), 90.0) << later << ": the slip is paid again";
        EXPECT_EQ(s["message"].get<std::string>().find("01-raycast"), std::string::npos);
    }

    // `raylab check` of 02 draws the student's own 01: it says so first.
    CommandResult check = runRaylab("check --stage 02 --lab " + quote(dir / "class" / "ann"));
    EXPECT_EQ(check.exitCode, 1) << check.all();
    const std::size_t said = check.out.find("01-raycast/find_closest.glsl, and its findClosest "
                                            "fails stage 01's check");
    EXPECT_NE(said, std::string::npos) << check.out;
    EXPECT_LT(said, check.out.find("function checks")) << "said first: " << check.out;
    EXPECT_NE(check.out.find("fix it there first (raylab check --stage 01 --lab "),
              std::string::npos);
    // Fixed in 01, the note is gone.
    replaceInFile(dir / "class" / "ann" / "01-raycast" / "find_closest.glsl",
                  "if (t != NO_HIT && hit.id < 0)", "if (t != NO_HIT && t < hit.t)");
    CommandResult fixed = runRaylab("check --stage 02 --lab " + quote(dir / "class" / "ann"));
    EXPECT_EQ(fixed.exitCode, 0) << fixed.all();
    EXPECT_EQ(fixed.out.find("fix it there first"), std::string::npos) << fixed.out;

    writeFile(dir / "bad.json", R"({"earlier_stages": "mine"})");
    CommandResult bad =
        runRaylab(args + quote(dir / "bad") + " --course " + quote(dir / "bad.json"));
    EXPECT_EQ(bad.exitCode, 2) << bad.all();
    EXPECT_NE(bad.err.find("earlier_stages: expected \"solved\""), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(dir / "bad"));
}

// `raylab check` prints the score the grader gives for the same checks: a
// course that grades without seeded views gives exactly that score.
TEST(Grade, CheckPrintsTheScoreGradingGivesForTheSameChecks) {
    ScratchDir dir;
    const fs::path lab = dir / "class" / "cy";
    writeSolvedLabs(lab);
    // 01: the first hit kept (views and findClosest fail); 03: the shadow ray
    // not offset (acne; its shadows-off view does not reach the stage's code).
    replaceInFile(lab / "01-raycast" / "find_closest.glsl", "if (t != NO_HIT && t < hit.t)",
                  "if (t != NO_HIT && hit.id < 0)");
    replaceInFile(lab / "03-shadows" / "light_visibility.glsl",
                  "Ray shadowRay = Ray(offsetRayOrigin(point, side), dir);",
                  "Ray shadowRay = Ray(point, dir);");
    writeFile(dir / "course.json", R"({"stages": {
        "01-raycast": {"grading": {"seeded_views": 0}},
        "03-shadows": {"grading": {"seeded_views": 0}}}})");
    CommandResult g = runRaylab("grade --submissions " + quote(dir / "class") +
                                " --stages 01,03 --jobs 2 --seed 9 --out " + quote(dir / "out") +
                                " --course " + quote(dir / "course.json"));
    ASSERT_EQ(g.exitCode, 0) << g.all();
    for (const char* stage : {"01-raycast", "03-shadows"}) {
        const nlohmann::json s = stageResult(dir / "out", "cy", stage);
        EXPECT_FALSE(fs::exists(dir / "out" / "students" / "cy" / stage / "seeded-1.png"));
        CommandResult c = runRaylab(std::string("check --stage ") + stage + " --lab " + quote(lab) +
                                    " --course " + quote(dir / "course.json"));
        std::smatch m;
        ASSERT_TRUE(std::regex_search(c.out, m, std::regex("score: ([0-9.]+)/100"))) << c.out;
        EXPECT_NEAR(std::stod(m[1]), s["score"].get<double>(), 0.005) << stage << "\n" << c.out;
        EXPECT_NE(c.out.find("your course grades exactly these checks"), std::string::npos);
        // Without the course file it says what else the grader draws.
        CommandResult plain =
            runRaylab(std::string("check --stage ") + stage + " --lab " + quote(lab));
        EXPECT_NE(plain.out.find("also draws 3 views close to these"), std::string::npos)
            << plain.out;
    }
}

// f3's isSilhouette table holds degenerate triangles whose neighbour faces
// the eye: comparing the two signs instead of testing their product (which a
// zero normal makes 0: no fin) fails there.
TEST(Grade, ComparingTheSilhouettesSignsFailsItsFunctionCheck) {
    ScratchDir dir;
    writeSolvedLabs(dir.path());
    CommandResult right = runRaylab("check --stage f3 --lab " + quote(dir.path()));
    EXPECT_NE(right.out.find("PASS isSilhouette"), std::string::npos) << right.out;
    replaceInFile(dir / "f3-fins" / "silhouette.glsl",
                  "return dot(pb, nAbc) * dot(pb, nBcd) < 0.0;",
                  "return (dot(pb, nAbc) < 0.0) != (dot(pb, nBcd) < 0.0);");
    CommandResult signs = runRaylab("check --stage f3 --lab " + quote(dir.path()));
    EXPECT_EQ(signs.exitCode, 1) << signs.all();
    EXPECT_NE(signs.out.find("FAIL isSilhouette"), std::string::npos) << signs.out;
    EXPECT_NE(signs.out.find("degenerate triangle"), std::string::npos) << signs.out;
}

// The report's known mistakes match the failing checks and the causes their
// hints name: two students whose only failing check is 04's trace, for two
// different causes (a secondary ray's offset, the stack's size), are told
// apart, and the two offset mistakes, which look alike in both, share one
// row: every catalogue entry is listed once.
TEST(Grade, TheReportsKnownMistakesReadTheHintsAndListAnEntryOnce) {
    ScratchDir dir;
    const struct {
        const char* student;
        const char* mistake;
    } class_[] = {{"ona", "reflected-ray-not-offset"}, {"sam", "stack-too-small"}};
    for (const auto& s : class_) {
        writeSolvedLabs(dir / "class" / s.student);
        const auto m = nlohmann::json::parse(readFile(sourceDir() / "tests/mistakes/04-recursion" /
                                                      (std::string(s.mistake) + ".json")));
        for (const auto& pair : m["replace"])
            replaceInFile(dir / "class" / s.student / "04-recursion" / m["file"].get<std::string>(),
                          pair[0], pair[1]);
    }
    CommandResult r = runRaylab("grade --submissions " + quote(dir / "class") +
                                " --stages 04 --jobs 2 --seed 3 --out " + quote(dir / "out"));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const std::string html = readFile(dir / "out" / "report.html");
    auto count = [&](const std::string& text) {
        std::size_t n = 0;
        for (std::size_t at = html.find(text); at != std::string::npos;
             at = html.find(text, at + 1))
            ++n;
        return n;
    };
    const std::string offset = "the reflected ray starts exactly on the surface";
    const std::string fixed = "the refracted ray starts a fixed 0.001 inside";
    const std::string stack = "a stack of 3 rays";
    EXPECT_EQ(count(offset), 1u) << html;
    EXPECT_EQ(count(fixed), 1u);
    EXPECT_EQ(count(stack), 1u);
    // One row for the two offset mistakes, matched once (ona); the stack's
    // row matched once (sam).
    const std::size_t row = html.find(offset);
    ASSERT_NE(row, std::string::npos);
    const std::string offsetRow = html.substr(row, html.find("</tr>", row) - row);
    EXPECT_NE(offsetRow.find(fixed), std::string::npos) << offsetRow;
    EXPECT_NE(offsetRow.find(">1</td>"), std::string::npos) << offsetRow;
    const std::size_t stackAt = html.find(stack);
    const std::string stackRow = html.substr(stackAt, html.find("</tr>", stackAt) - stackAt);
    EXPECT_NE(stackRow.find(">1</td>"), std::string::npos) << stackRow;
    EXPECT_EQ(count("No failure repeats"), 0u);
}
