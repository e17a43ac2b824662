// `raylab mutants` end to end on stage 03, the smallest (6 mutants, about
// 5 s): its survivors are exactly the ones tests/mutants/03-shadows.txt
// explains, and the same run against a list without them fails. The whole
// sample of every stage is `ctest -L mutants`.
#include "known_survivors.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

using namespace raylab::test;

TEST(Mutants, AnUnlistedSurvivorFailsAndTheListedOnesAreTheSurvivors) {
    ScratchDir d;
    fs::create_directories(d / "empty-list");
    CommandResult r =
        runRaylab("mutants --stage 03 --jobs 2 --seed 1 --out " + quote((d / "out").string()) +
                  " --known " + quote((d / "empty-list").string()));
    ASSERT_EQ(r.exitCode, 1) << r.all();
    EXPECT_NE(r.out.find("03-shadows: caught 4 of 6"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("NEW SURVIVOR"), std::string::npos) << r.out;
    EXPECT_NE(readFile(d / "out/mutants.md").find("## Survivors"), std::string::npos);

    std::set<std::string> survivors;
    std::istringstream in(readFile(d / "out/survivors.txt"));
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') survivors.insert(line);
    std::set<std::string> listed;
    for (const auto& [id, known] :
         raylab::parseKnownSurvivors(readFile(sourceDir() / "tests/mutants/03-shadows.txt"), "03"))
        listed.insert(id);
    EXPECT_EQ(survivors, listed);

    // Without --known the survivors are listed without reasons: the output
    // says where the reasons are.
    CommandResult bare =
        runRaylab("mutants --stage 03 --jobs 2 --seed 1 --out " + quote((d / "bare").string()));
    ASSERT_EQ(bare.exitCode, 0) << bare.all();
    EXPECT_NE(bare.out.find("--known tests/mutants"), std::string::npos) << bare.out;
}

TEST(Mutants, BadInputIsOneLineAndLeavesNothing) {
    ScratchDir d;
    for (const std::string& args :
         {std::string("--stage 99"), std::string("--stage 03 --jobs 0"),
          std::string("--stage 03 --max -1"),
          std::string("--stage 03 --known ") + quote((d / "missing").string())}) {
        CommandResult r = runRaylab("mutants " + args + " --out " + quote((d / "out").string()));
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.all();
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(d / "out")) << args;
    }
}
