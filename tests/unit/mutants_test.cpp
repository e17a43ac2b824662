// The mutant generator of `raylab mutants` (mutants.h) and the list of
// explained survivors (known_survivors.h).
#include "error.h"
#include "known_survivors.h"
#include "lab_markers.h"
#include "mutants.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {

const std::string kMutantMarked = "float f(vec3 a, float b)\n"                // 1
                                  "{\n"                                       // 2
                                  "    if (b < 1.0) return 0.0;  // a < b\n"  // 3: not in a region
                                  "    // TODO(1.a): compute f\n"             // 4
                                  "    //@solution\n"                         // 5
                                  "    if (b < 0.0) return -b;  // x + y\n"   // 6
                                  "    # define NOT_CODE 1 + 2\n"             // 7
                                  "    /* a * b */ float c = min(a.x, 2.0) * b;\n"  // 8
                                  "    return length(normalize(a)) - c;\n"          // 9
                                  "    //@stub\n"                                   // 10
                                  "    //@ return 0.0;\n"                           // 11
                                  "    //@end\n"                                    // 12
                                  "}\n";

std::vector<std::string> ids(const std::vector<Mutant>& mutants) {
    std::vector<std::string> out;
    for (const Mutant& m : mutants) out.push_back(mutantId(m));
    return out;
}

}  // namespace

TEST(Mutants, SolutionLinesAreThoseBetweenSolutionAndStub) {
    EXPECT_EQ(solutionLineNumbers(kMutantMarked), (std::vector<int>{6, 7, 8, 9}));
}

TEST(Mutants, GeneratesTheExpectedMutantsOfTheSolutionCodeOnly) {
    const std::vector<std::string> expected = {
        R"(f.glsl | if (b < 0.0) return -b; | "<" -> "<=")",
        R"(f.glsl | if (b < 0.0) return -b; | "<" -> ">")",
        R"(f.glsl | if (b < 0.0) return -b; | "-" -> "")",  // after "return": unary
        R"(f.glsl | float c = min(a.x, 2.0) * b; | "min" -> "max")",
        R"(f.glsl | float c = min(a.x, 2.0) * b; | "2.0" -> "0.0")",
        R"(f.glsl | float c = min(a.x, 2.0) * b; | "*" -> "/")",
        R"(f.glsl | return length(normalize(a)) - c; | "normalize(" -> "(")",
        R"(f.glsl | return length(normalize(a)) - c; | "-" -> "+")",
    };
    EXPECT_EQ(ids(generateMutants("f.glsl", kMutantMarked)), expected);
}

TEST(Mutants, AppliedMutantChangesOneTokenOfItsLine) {
    const std::vector<Mutant> all = generateMutants("f.glsl", kMutantMarked);
    ASSERT_EQ(all.size(), 8u);
    std::string m = applyMutant(kMutantMarked, all[6]);
    EXPECT_NE(m.find("    return length((a)) - c;\n"), std::string::npos);
    m = applyMutant(kMutantMarked, all[2]);
    EXPECT_NE(m.find("    if (b < 0.0) return b;  // x + y\n"), std::string::npos);
    // Nothing else changed: undoing the one line gives the original.
    EXPECT_EQ(m.size() + 1, kMutantMarked.size());
}

TEST(Mutants, OperatorsAndNumbers) {
    auto changes = [](const std::string& code) {
        std::vector<std::string> out;
        for (const Mutant& m :
             generateMutants("g", "// TODO(x): y\n//@solution\n" + code + "\n//@stub\n//@end\n"))
            out.push_back(m.from + ">" + m.to);
        return out;
    };
    EXPECT_EQ(changes("a = b >= c && d != 0;"),
              (std::vector<std::string>{">=>>", ">=><=", "&&>||", "!=>=="}));
    EXPECT_EQ(changes("x += 1e-3 / y; i++;"),
              (std::vector<std::string>{"+=>-=", "1e-3>0.0", "/>*"}));
    EXPECT_EQ(changes("uint u = 3u; int k = 0x0; float z = 0.0;"),
              (std::vector<std::string>{"3u>0u"}));
    // A minus that starts a continued line is binary when the line above ended an operand.
    EXPECT_EQ(changes("float v = a\n    - b;"), (std::vector<std::string>{"->+"}));
}

TEST(Mutants, SameLineTwiceGetsAnOccurrenceNumber) {
    const std::string text =
        "// TODO(x): y\n//@solution\nt = a < b;\nt = a < b;\n//@stub\n//@end\n";
    const std::vector<std::string> got = ids(generateMutants("h", text));
    ASSERT_EQ(got.size(), 4u);
    EXPECT_EQ(got[0], R"(h | t = a < b; | "<" -> "<=")");
    EXPECT_EQ(got[2], R"(h | t = a < b; | "<" -> "<=" #2)");
}

TEST(Mutants, IdsDoNotDependOnLineNumbersOrComments) {
    const std::string edited = "// a new first line\n" + kMutantMarked;
    std::string recommented = kMutantMarked;
    recommented.replace(recommented.find("// x + y"), 8, "// another comment");
    EXPECT_EQ(ids(generateMutants("f.glsl", edited)),
              ids(generateMutants("f.glsl", kMutantMarked)));
    EXPECT_EQ(ids(generateMutants("f.glsl", recommented)),
              ids(generateMutants("f.glsl", kMutantMarked)));
}

TEST(Mutants, SampleIsDeterministicAndKeepsTheOrder) {
    const std::vector<Mutant> all = generateMutants("f.glsl", kMutantMarked);
    const std::vector<Mutant> a = sampleMutants(all, 3, 7), b = sampleMutants(all, 3, 7);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(ids(a), ids(b));
    for (std::size_t i = 1; i < a.size(); ++i)  // in the file's order
        EXPECT_LE(std::make_pair(a[i - 1].line, a[i - 1].column),
                  std::make_pair(a[i].line, a[i].column));
    EXPECT_EQ(sampleMutants(all, 0, 7).size(), all.size());
    EXPECT_EQ(sampleMutants(all, 100, 7).size(), all.size());
}

TEST(KnownSurvivors, AnUnlistedSurvivorIsReported) {
    const std::string text = "# explained survivors\n"
                             "f.glsl | if (b < 0.0) return -b; | \"<\" -> \"<=\"\n"
                             "    why: at b = 0, -b and 0.0 are the same\n"
                             "\n"
                             "f.glsl | float c = min(a.x, 2.0) * b; | \"2.0\" -> \"0.0\"\n"
                             "    not equivalent: no view has a.x above 2\n";
    const auto known = parseKnownSurvivors(text, "k.txt");
    ASSERT_EQ(known.size(), 2u);
    const std::vector<std::string> survivors = {R"(f.glsl | if (b < 0.0) return -b; | "<" -> "<=")",
                                                R"(f.glsl | if (b < 0.0) return -b; | "<" -> ">")"};
    EXPECT_TRUE(known.at(survivors[0]).equivalent);
    EXPECT_EQ(known.at(survivors[0]).reason, "why: at b = 0, -b and 0.0 are the same");
    EXPECT_FALSE(known.at(R"(f.glsl | float c = min(a.x, 2.0) * b; | "2.0" -> "0.0")").equivalent);
    EXPECT_EQ(unlistedSurvivors(survivors, known), (std::vector<std::string>{survivors[1]}));
    EXPECT_TRUE(unlistedSurvivors({survivors[0]}, known).empty());
}

TEST(KnownSurvivors, EveryEntryNeedsItsReason) {
    EXPECT_THROW(parseKnownSurvivors("a | b | \"<\" -> \">\"\n", "k.txt"), Error);
    EXPECT_THROW(parseKnownSurvivors("a | b | \"<\" -> \">\"\n    because\n", "k.txt"), Error);
    EXPECT_THROW(parseKnownSurvivors("    why: nothing\n", "k.txt"), Error);
    EXPECT_THROW(parseKnownSurvivors("x\n  why: 1\nx\n  why: 2\n", "k.txt"), Error);
    try {
        parseKnownSurvivors("x\n  why: 1\ny\nz\n  why: 2\n", "k.txt");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("k.txt:3: ", 0), 0u) << e.what();
    }
}
