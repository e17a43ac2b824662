// The function checks' expected values as data (function_tables.h), which the
// page's core scores against instead of running the references: the shipped
// web/function_tables.json is what the references give, every value comes
// back exactly, and a table that no longer fits the checks is refused with
// its file and function named.
#include "error.h"
#include "function_tables.h"
#include "paths.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;

namespace {

bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("'" + from + "' not in the tables");
    return text.replace(at, from.size(), to);
}

}  // namespace

TEST(FunctionTables, TheShippedFileIsWhatTheReferencesGive) {
    // (raylab function-tables --out web/function_tables.json writes it again.)
    EXPECT_EQ(readTextFile(projectRoot() / "web" / "function_tables.json"), functionTablesJson());
}

TEST(FunctionTables, EveryValueComesBackExactly) {
    const FunctionTables tables = parseFunctionTables(functionTablesJson(), "tables");
    ASSERT_EQ(tables.size(), functionSpecs().size());
    int values = 0;
    for (const FunctionSpec& spec : functionSpecs()) {
        const std::vector<glm::dvec4> want = referenceWants(spec);
        const FunctionTable& t = tables.at(spec.name);
        ASSERT_EQ(t.wants.size(), want.size()) << spec.name;
        for (std::size_t i = 0; i < want.size(); ++i)
            for (int k = 0; k < 4; ++k, ++values)
                EXPECT_TRUE(same(t.wants[i][k], want[i][k]))
                    << spec.name << " case " << i << ": " << t.wants[i][k] << " vs " << want[i][k];
    }
    EXPECT_GT(values, 400);
}

TEST(FunctionTables, ScoringAgainstTheTableIsScoringAgainstTheReference) {
    const FunctionTables tables = parseFunctionTables(functionTablesJson(), "tables");
    for (const FunctionSpec& spec : functionSpecs()) {
        // The reference's own values as the harness's answers, and one wrong.
        std::vector<glm::vec4> results;
        for (const glm::dvec4& w : referenceWants(spec)) results.emplace_back(glm::vec4(w));
        results.front() += glm::vec4(0.25f, 0.25f, 0.25f, 0.0f);
        const FunctionOutcome a = scoreFunctionResults(spec, results);
        const FunctionOutcome b = scoreFunctionResults(spec, results, tables.at(spec.name).wants);
        EXPECT_EQ(a.passed, b.passed) << spec.name;
        EXPECT_EQ(a.firstFailure, b.firstFailure) << spec.name;
    }
}

TEST(FunctionTables, ATableThatNoLongerFitsIsRefused) {
    const std::string good = functionTablesJson();
    EXPECT_THROW(parseFunctionTables("{", "f.json"), Error);
    try {
        parseFunctionTables(replaced(good, "\"intersectSphere\"", "\"intersectSphre\""), "f.json");
        ADD_FAILURE() << "a renamed function was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("f.json: intersectSphere: missing"), std::string::npos)
            << e.what();
    }
    const std::string label = functionSpecs().front().cases.front().label;
    try {
        parseFunctionTables(replaced(good, "\"" + label + "\"", "\"renamed\""), "f.json");
        ADD_FAILURE() << "a renamed case was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("the check's is \"" + label), std::string::npos)
            << e.what();
    }
}

TEST(FunctionTables, ABundlesTablesHoldItsChecksAndTheirHarness) {
    // A bundle of stage 03 holds lightVisible's table, stand-ins and helpers,
    // and nothing of 08's lightVisibleFast (whose stand-in finds blockers).
    const FunctionSpec& released = functionSpec("lightVisible");
    const std::string text = functionTablesJson({&released}, {&findStage("03")});
    EXPECT_EQ(text.find("lightVisibleFast"), std::string::npos);
    EXPECT_EQ(text.find("findBlocker"), std::string::npos);
    const FunctionTables some = parseFunctionTables(text, "b.json", TableCoverage::Some);
    ASSERT_EQ(some.size(), 1u);
    EXPECT_NE(text.find("\"counts\": {}"), std::string::npos) << "03 has no count check";
    const FunctionSpec rebuilt = withHarnessFrom(some, released, "b.json");
    EXPECT_FALSE(rebuilt.prelude.empty());
    EXPECT_EQ(rebuilt.prelude, released.prelude);
    EXPECT_EQ(rebuilt.helpers, released.helpers);
    // The project's file must hold every check: a bundle's is refused there.
    try {
        parseFunctionTables(text, "b.json");
        ADD_FAILURE() << "a partial table was taken for the whole";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("b.json: intersectSphere: missing"), std::string::npos)
            << e.what();
    }
    // A check the bundle does not hold: one line naming the file and the function.
    try {
        withHarnessFrom(some, functionSpec("lightVisibleFast"), "b.json");
        ADD_FAILURE() << "a check without a table was given a harness";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("b.json has no table for lightVisibleFast"),
                  std::string::npos)
            << e.what();
    }
    // A function no check has is refused, not ignored.
    try {
        parseFunctionTables(replaced(text, "\"lightVisible\"", "\"lightInvisible\""), "b.json",
                            TableCoverage::Some);
        ADD_FAILURE() << "an unknown function was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("lightInvisible: no such function check"),
                  std::string::npos)
            << e.what();
    }
}

// The cases a float answer may call either way (an edge-on silhouette) are
// marked in the tables: a build without the reference that decides them
// (silhouette.h) takes them from there.
TEST(FunctionTables, TheCasesEitherAnswerPassesComeWithTheTables) {
    const FunctionTables tables = parseFunctionTables(functionTablesJson(), "tables");
    int either = 0;
    for (const FunctionSpec& spec : functionSpecs()) {
        FunctionSpec blank = spec;
        for (FunctionCase& c : blank.cases) c.hitOrMiss = false;
        const FunctionSpec rebuilt = withHarnessFrom(tables, blank, "tables");
        for (std::size_t i = 0; i < spec.cases.size(); ++i) {
            EXPECT_EQ(rebuilt.cases[i].hitOrMiss, spec.cases[i].hitOrMiss)
                << spec.name << ": " << spec.cases[i].label;
            either += spec.cases[i].hitOrMiss && spec.name == "isSilhouette";
        }
    }
    EXPECT_GT(either, 0) << "isSilhouette has edge-on cases";
    EXPECT_THROW(parseFunctionTables(
                     replaced(functionTablesJson(), "\"either\":true", "\"either\":1"), "tables"),
                 Error);
}
