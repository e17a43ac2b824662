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
