// The solution -> lab transformation (tools/labgen).
#include "error.h"
#include "lab_markers.h"

#include <gtest/gtest.h>

using namespace raylab;

namespace {
const std::string kMarked = "float f()\n"
                            "{\n"
                            "    // TODO(1.a): compute f\n"
                            "    //     (a second line of explanation)\n"
                            "    //@solution\n"
                            "    return 42.0;\n"
                            "    //@stub\n"
                            "    //@ labTodo();\n"
                            "    //@ return 0.0;\n"
                            "    //@end\n"
                            "}\n";
}

TEST(LabMarkers, LabFormKeepsTheTodoAndPutsTheStubInPlaceOfTheSolution) {
    EXPECT_EQ(
        transformMarkedSource(kMarked, MarkedForm::Lab, "f.glsl"),
        "float f()\n{\n    // TODO(1.a): compute f\n    //     (a second line of explanation)\n"
        "    labTodo();\n    return 0.0;\n}\n");
}

TEST(LabMarkers, SolvedFormKeepsOnlyTheSolution) {
    EXPECT_EQ(transformMarkedSource(kMarked, MarkedForm::Solved, "f.glsl"),
              "float f()\n{\n    return 42.0;\n}\n");
}

TEST(LabMarkers, TextWithoutMarkersIsUnchanged) {
    const std::string plain = "// TODO(2): an ordinary comment\nint x;\n";
    EXPECT_EQ(transformMarkedSource(plain, MarkedForm::Lab, "p.glsl"), plain);
    EXPECT_EQ(transformMarkedSource(plain, MarkedForm::Solved, "p.glsl"), plain);
}

TEST(LabMarkers, MalformedRegionsAreErrorsWithFileAndLine) {
    const std::pair<std::string, std::string> cases[] = {
        {"int x;\n//@solution\nx;\n//@stub\n//@end\n", "f.glsl:2: //@solution needs"},
        {"// TODO(1): t\n//@solution\nx;\n//@stub\n//@ y;\n", "f.glsl:2: region not closed"},
        {"// TODO(1): t\n//@solution\nx;\n//@stub\ny;\n//@end\n",
         "f.glsl:5: stub lines must start"},
        {"int x;\n//@end\n", "f.glsl:2: marker '//@end' outside"},
        {"// TODO(1): t\n//@solution\nx;\n//@end\n", "f.glsl:4: expected //@stub"},
    };
    for (const auto& [text, expected] : cases) {
        try {
            transformMarkedSource(text, MarkedForm::Lab, "f.glsl");
            ADD_FAILURE() << "no error for:\n" << text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
                << "expected '" << expected << "', got '" << e.what() << "'";
        }
    }
}

namespace {
// An open region around a guided body with a solution region of its own.
const std::string kOpen = "float f(float x)\n"
                          "{\n"
                          "    //@open\n"
                          "    //@ // TODO(1.a): return f(x), the contract only\n"
                          "    //@ labTodo();\n"
                          "    //@ return 0.0;\n"
                          "    //@guided\n"
                          "    float y = x * x;  // given at the guided level\n"
                          "    // TODO(1.a): add one\n"
                          "    //@solution\n"
                          "    y += 1.0;\n"
                          "    //@stub\n"
                          "    //@ labTodo();\n"
                          "    //@end\n"
                          "    return y;\n"
                          "    //@end-open\n"
                          "}\n";
}  // namespace

TEST(LabMarkers, OpenLabKeepsOnlyTheOpenStub) {
    EXPECT_EQ(transformMarkedSource(kOpen, MarkedForm::Lab, "f.glsl", Level::Open),
              "float f(float x)\n{\n    // TODO(1.a): return f(x), the contract only\n"
              "    labTodo();\n    return 0.0;\n}\n");
}

TEST(LabMarkers, GuidedLabIgnoresTheOpenRegion) {
    EXPECT_EQ(transformMarkedSource(kOpen, MarkedForm::Lab, "f.glsl", Level::Guided),
              "float f(float x)\n{\n    float y = x * x;  // given at the guided level\n"
              "    // TODO(1.a): add one\n    labTodo();\n    return y;\n}\n");
}

TEST(LabMarkers, SolvedFormIsTheSameAtBothLevels) {
    const std::string solved = "float f(float x)\n{\n    float y = x * x;  // given at the guided "
                               "level\n    y += 1.0;\n    return y;\n}\n";
    EXPECT_EQ(transformMarkedSource(kOpen, MarkedForm::Solved, "f.glsl", Level::Guided), solved);
    EXPECT_EQ(transformMarkedSource(kOpen, MarkedForm::Solved, "f.glsl", Level::Open), solved);
}

TEST(LabMarkers, StudentCodeLinesCountWhatEachLevelTakesAway) {
    EXPECT_EQ(studentCodeLines(kOpen, Level::Guided), 1);  // y += 1.0
    EXPECT_EQ(studentCodeLines(kOpen, Level::Open), 3);    // the whole body
    EXPECT_EQ(studentCodeLines(kMarked, Level::Open), 1);  // no open region: as guided
}

TEST(LabMarkers, MalformedOpenRegionsAreErrorsWithFileAndLine) {
    const std::pair<std::string, std::string> cases[] = {
        {"//@open\n//@ a;\nb;\n", "f.glsl:3: an //@open region's stub lines"},
        {"//@open\n//@ a;\n", "f.glsl:1: //@open region without //@guided"},
        {"//@open\n//@ a;\n//@guided\nb;\n", "f.glsl:1: //@open region not closed"},
        {"//@open\n//@guided\n//@open\n", "f.glsl:3: //@open inside the open region opened on "
                                          "line 1"},
        {"x;\n//@end-open\n", "f.glsl:2: marker '//@end-open' outside"},
        {"//@guided\n", "f.glsl:1: marker '//@guided' outside"},
        {"//@open\n//@guided\n// TODO(1): t\n//@solution\nx;\n//@end-open\n",
         "f.glsl:6: expected //@stub"},
    };
    for (const auto& [text, expected] : cases)
        for (Level level : {Level::Guided, Level::Open}) {
            try {
                transformMarkedSource(text, MarkedForm::Lab, "f.glsl", level);
                ADD_FAILURE() << "no error for:\n" << text;
            } catch (const Error& e) {
                EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
                    << "expected '" << expected << "', got '" << e.what() << "'";
            }
        }
}

TEST(LabMarkers, LevelNamesRoundTripAndUnknownOnesAreRefused) {
    EXPECT_EQ(parseLevel("open"), Level::Open);
    EXPECT_EQ(parseLevel(levelName(Level::Guided)), Level::Guided);
    EXPECT_THROW(parseLevel("expert"), Error);
}
