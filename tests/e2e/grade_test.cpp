// `raylab grade` on small classes: output files, determinism, the seed, bad
// arguments. (The class of 30 with every broken case is grade_class_test.cpp.)
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace raylab::test;

namespace {

// A class of two: a solved copy of the labs and the untouched labs, with
// stage 02 missing from the second.
void makeClass(const fs::path& dir) {
    writeSolvedLabs(dir / "ada");
    fs::copy(sourceDir() / "labs", dir / "bob", fs::copy_options::recursive);
    fs::remove_all(dir / "bob" / "02-shading");
}

} // namespace

TEST(Grade, WritesEveryReportAndGivesTheSameScoresTwice) {
    ScratchDir dir;
    makeClass(dir / "class");
    const std::string args = "grade --submissions " + quote((dir / "class").string()) + " --stages 01,02 --jobs 2 --seed 11 --out ";
    CommandResult first = runRaylab(args + quote((dir / "a").string()));
    ASSERT_EQ(first.exitCode, 0) << first.all();
    CommandResult second = runRaylab(args + quote((dir / "b").string()));
    ASSERT_EQ(second.exitCode, 0) << second.all();

    for (const char* f : {"report.html", "summary.csv", "junit.xml", "ada/results.json", "bob/results.json"})
        EXPECT_TRUE(fs::exists(dir / "a" / f)) << f;
    EXPECT_EQ(readFile(dir / "a" / "summary.csv"), readFile(dir / "b" / "summary.csv")) << "grading must be deterministic";
    auto ada = nlohmann::json::parse(readFile(dir / "a" / "ada" / "results.json"));
    EXPECT_DOUBLE_EQ(ada["score"].get<double>(), 200.0);
    auto bob = nlohmann::json::parse(readFile(dir / "a" / "bob" / "results.json"));
    EXPECT_LT(bob["score"].get<double>(), 10.0);
    EXPECT_NE(readFile(dir / "a" / "summary.csv").find("02-shading: not submitted"), std::string::npos);
    // The seeded views exist and are graded like the others.
    EXPECT_TRUE(fs::exists(dir / "a" / "ada" / "01-raycast" / "seeded-1.png"));
    EXPECT_TRUE(fs::exists(dir / "a" / "reference" / "01-raycast" / "seeded-3.png"));
    // No temporary files anywhere.
    for (const auto& e : fs::recursive_directory_iterator(dir / "a"))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(Grade, AnotherSeedGivesOtherViews) {
    ScratchDir dir;
    writeSolvedLabs(dir / "class" / "ada");
    for (const char* seed : {"1", "2"}) {
        CommandResult r = runRaylab("grade --submissions " + quote((dir / "class").string()) + " --stages 01 --seed " + seed + " --out " +
                                    quote((dir / seed).string()));
        ASSERT_EQ(r.exitCode, 0) << r.all();
    }
    EXPECT_NE(readFile(dir / "1" / "reference" / "01-raycast" / "seeded-1.png"), readFile(dir / "2" / "reference" / "01-raycast" / "seeded-1.png"));
    EXPECT_EQ(readFile(dir / "1" / "reference" / "01-raycast" / "front.png"), readFile(dir / "2" / "reference" / "01-raycast" / "front.png"));
}

TEST(Grade, BadArgumentsAreOneLineErrors) {
    ScratchDir dir;
    fs::create_directories(dir / "empty");
    writeSolvedLabs(dir / "class" / "ada");
    const std::string cls = " --submissions " + quote((dir / "class").string()) + " --out " + quote((dir / "out").string());
    struct Case {
        std::string args, expected;
    } cases[] = {
        {"grade --submissions /nonexistent --out " + quote((dir / "o").string()), "--submissions '/nonexistent': no such folder"},
        {"grade --submissions " + quote((dir / "empty").string()) + " --out " + quote((dir / "o").string()), "no student folders"},
        {"grade" + cls + " --stages 01,42", "unknown stage '42'"},
        {"grade" + cls + " --jobs 0", "--jobs must be between 1 and 64"},
        {"grade" + cls + " --timeout -1", "--timeout must be between"},
        {"grade" + cls + " --memory-mb 5", "--memory-mb must be 0"},
    };
    for (const Case& c : cases) {
        CommandResult r = runRaylab(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.all();
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}
