// Assembling shaders from files: includes, defines, and mapping compiler
// errors back to the file and line the student wrote.
#include "error.h"
#include "shader_constants.h"
#include "shader_source.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace raylab;
using raylab::test::ScratchDir;
using raylab::test::writeFile;

namespace {

// Assembled line number (1-based) of the first line containing NEEDLE.
int lineOf(const ShaderSource& s, const std::string& needle) {
    std::istringstream in(s.text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
        if (line.find(needle) != std::string::npos) return n;
    return -1;
}

struct Tree {
    ScratchDir dir;
    Tree() {
        writeFile(dir / "stage/main.frag",
                  "// main\n#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() { int m; }\n");
        writeFile(dir / "stage/a.glsl", "#include \"b.glsl\"\nint a;\n");
        writeFile(dir / "shared/b.glsl", "// b line 1\nint b;  // b line 2\n");
    }
    std::vector<fs::path> search() const { return {dir / "stage", dir / "shared"}; }
};

}  // namespace

TEST(ShaderSource, VersionAndDefinesComeFirst) {
    Tree t;
    ShaderSource s = assembleShader("main.frag", t.search(), {"MAX_SPHERES 16", "SHADOWS"});
    EXPECT_EQ(s.text.rfind("#version 330 core\n#define MAX_SPHERES 16\n#define SHADOWS\n", 0), 0u)
        << s.text;
}

TEST(ShaderSource, IncludesAreResolvedOnceThroughTheSearchPath) {
    Tree t;
    ShaderSource s = assembleShader("main.frag", t.search(), {});
    EXPECT_EQ(s.files.size(), 3u);
    std::size_t first = s.text.find("int b;");
    ASSERT_NE(first, std::string::npos);
    EXPECT_EQ(s.text.find("int b;", first + 1), std::string::npos) << "b.glsl was included twice";
    EXPECT_LT(s.text.find("int b;"), s.text.find("int a;")) << "a.glsl includes b.glsl first";
}

TEST(ShaderSource, EveryAssembledLineKnowsItsFileAndLine) {
    Tree t;
    ShaderSource s = assembleShader("main.frag", t.search(), {"X 1"});
    SourceLine b = s.where(lineOf(s, "int b;"));
    EXPECT_NE(b.file.find("shared/b.glsl"), std::string::npos) << b.file;
    EXPECT_EQ(b.line, 2);
    SourceLine m = s.where(lineOf(s, "void main"));
    EXPECT_NE(m.file.find("stage/main.frag"), std::string::npos) << m.file;
    EXPECT_EQ(m.line, 4);
    EXPECT_EQ(s.where(1).file, "<raylab>");
}

TEST(ShaderSource, FirstDirectoryWinsSoALaterStageCanReplaceAFile) {
    Tree t;
    writeFile(t.dir / "stage/b.glsl", "int replacedB;\n");
    ShaderSource s = assembleShader("main.frag", t.search(), {});
    EXPECT_NE(s.text.find("replacedB"), std::string::npos);
    EXPECT_EQ(s.text.find("int b;"), std::string::npos);
}

TEST(ShaderSource, MissingIncludeNamesTheIncludingFileAndLine) {
    Tree t;
    writeFile(t.dir / "stage/a.glsl", "int a;\n#include \"nope.glsl\"\n");
    try {
        assembleShader("main.frag", t.search(), {});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        std::string msg = e.what();
        EXPECT_NE(msg.find("stage/a.glsl:2: cannot find shader file \"nope.glsl\""),
                  std::string::npos)
            << msg;
    }
}

TEST(ShaderSource, AFileWithNulBytesIsNamedAsSuch) {
    Tree t;
    writeFile(t.dir / "stage/a.glsl", std::string("int a;\nint\0b;\n", 14));
    try {
        assembleShader("main.frag", t.search(), {});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        std::string msg = e.what();
        EXPECT_NE(msg.find("stage/a.glsl:2: the file holds NUL bytes"), std::string::npos) << msg;
    }
}

TEST(ShaderSource, IncludesCannotLeaveTheSearchPath) {
    Tree t;
    for (const char* bad : {"../secret.glsl", "/etc/passwd", "sub/../../x.glsl"}) {
        writeFile(t.dir / "stage/a.glsl", std::string("#include \"") + bad + "\"\n");
        EXPECT_THROW(assembleShader("main.frag", t.search(), {}), Error) << bad;
    }
}

TEST(ShaderSource, MapsMesaNvidiaAndGlslangLogs) {
    Tree t;
    ShaderSource s = assembleShader("main.frag", t.search(), {});
    int n = lineOf(s, "int b;");
    std::string log = "0:" + std::to_string(n) + "(5): error: syntax error\n" +       // Mesa
                      "0(" + std::to_string(n) + ") : error C0000: syntax error\n" +  // NVIDIA
                      "ERROR: 0:" + std::to_string(n) +
                      ": 'x' : undeclared identifier\n" +  // glslang
                      "something else\n";
    std::string mapped = mapCompilerLog(log, s);
    std::string file = s.where(n).file;
    EXPECT_NE(mapped.find(file + ":2:5: error: syntax error"), std::string::npos) << mapped;
    EXPECT_NE(mapped.find(file + ":2: error C0000: syntax error"), std::string::npos) << mapped;
    EXPECT_NE(mapped.find(file + ":2: error: 'x' : undeclared identifier"), std::string::npos)
        << mapped;
    EXPECT_NE(mapped.find("something else"), std::string::npos) << mapped;
}

TEST(ShaderSource, FindsOpenTodosOutsideComments) {
    ScratchDir dir;
    writeFile(dir / "s/main.frag", "// TODO(9.a): do the thing\n"
                                   "//     with more words.\n"
                                   "// Not part of the title: its sentence ended.\n"
                                   "labTodo();\n"
                                   "// labTodo(); in a comment does not count\n"
                                   "    x = 1; // TODO(9.b): done already, no stub call\n"
                                   "// TODO(9.c): a sentence cut by a\n"
                                   "// Checked by: line, which never joins\n"
                                   "labTodo();\n");
    ShaderSource s = assembleShader("main.frag", {dir / "s"}, {});
    auto todos = findOpenTodos(s);
    ASSERT_EQ(todos.size(), 2u);
    EXPECT_EQ(todos[0].line, 4);
    EXPECT_EQ(todos[0].title, "TODO(9.a): do the thing with more words.");
    EXPECT_EQ(todos[1].title, "TODO(9.c): a sentence cut by a");
}

// The constants GLSL and C++ share are written into every shader from the
// C++ definitions, with the values the C++ uses.
TEST(ShaderSource, SharedConstantsComeFromTheCpp) {
    Tree t;
    ShaderSource s = assembleShader("main.frag", t.search(), {});
    auto floatOf = [&](const std::string& name) {
        // T_MIN's default stands in the #else of the stage's own RAYLAB_T_MIN.
        const std::string key =
            (name == "T_MIN" ? "#else\n" : "") + std::string("const float ") + name + " = ";
        auto at = s.text.find(key);
        EXPECT_NE(at, std::string::npos) << name;
        return at == std::string::npos ? 0.0f : std::stof(s.text.substr(at + key.size()));
    };
    auto intOf = [&](const std::string& name) {
        const std::string key = "const int " + name + " = ";
        auto at = s.text.find(key);
        EXPECT_NE(at, std::string::npos) << name;
        return at == std::string::npos ? -1 : std::stoi(s.text.substr(at + key.size()));
    };
    using namespace raylab::shader;
    EXPECT_EQ(floatOf("T_MIN"), float(kTMin));
    EXPECT_NE(s.text.find("#ifdef RAYLAB_T_MIN\nconst float T_MIN = RAYLAB_T_MIN;"),
              std::string::npos)
        << "a stage may set its own T_MIN (stage 03: 0.0)";
    EXPECT_EQ(floatOf("NO_HIT"), float(kNoHit));
    EXPECT_EQ(floatOf("T_FAR"), float(kTFar));
    EXPECT_EQ(intOf("MAX_DEPTH"), kMaxDepth);
    EXPECT_EQ(intOf("MAX_RAYS"), kMaxRays);
    EXPECT_EQ(intOf("KIND_TORUS"), kTorus);
    EXPECT_EQ(intOf("KIND_MESH"), kMesh);
    EXPECT_EQ(intOf("OBJECT_KIND_STRIDE"), kObjectKindStride);
    // Generated lines, not the student's: errors never point into them.
    const int line =
        int(std::count(s.text.begin(), s.text.begin() + long(s.text.find("const float T_MIN")),
                       '\n')) +
        1;
    EXPECT_EQ(s.where(line).file, "<raylab>");
}

// Found by tests/fuzz/fuzz_shader_source: std::regex (libstdc++) recurses once
// per character, so one long line - an #include with a long comment, long
// indentation, a long #version line, a long line of code or a long TODO
// title - overflowed the stack (a crash, not an Error). Lines of any length
// must work; a graded submission is untrusted input.
TEST(ShaderSource, VeryLongLinesDoNotOverflowTheStack) {
    const std::size_t n = 2000000;
    ScratchDir dir;
    writeFile(dir / "s/main.frag",
              "#version 330 core // " + std::string(n, 'v') + "\n" + "#include \"a.glsl\" // " +
                  std::string(n, 'c') + "\n" + std::string(n, ' ') + "#include \"b.glsl\"\n" +
                  "// TODO(9.a): " + std::string(n, 't') + "\n" + "float x[] = float[](" +
                  std::string(n, '1') + "); labTodo();\n");
    writeFile(dir / "s/a.glsl", "int a;\n");
    writeFile(dir / "s/b.glsl", "int b;\n");
    ShaderSource s = assembleShader("main.frag", {dir / "s"}, {});
    EXPECT_EQ(s.files.size(), 3u);
    EXPECT_NE(s.text.find("int a;\nint b;\n"), std::string::npos);
    EXPECT_EQ(s.text.find("vvvv"), std::string::npos) << "the #version line becomes a blank line";
    auto todos = findOpenTodos(s);
    ASSERT_EQ(todos.size(), 1u);
    EXPECT_EQ(todos[0].line, 5);
    EXPECT_EQ(todos[0].title, "TODO(9.a): " + std::string(n, 't'));
    std::string log = "0:2(1): error: " + std::string(n, 'e') + "\n";
    EXPECT_NE(mapCompilerLog(log, s).find(": error: eee"), std::string::npos);
}

// A line number too long for an int was passed to std::stoi, which threw
// std::out_of_range (not an Error). Such a line is not a reference: kept as is.
TEST(ShaderSource, HugeLineNumbersInALogAreKeptAsTheyAre) {
    Tree t;
    ShaderSource s = assembleShader("main.frag", t.search(), {});
    std::string log =
        "0:99999999999(1): error: x\n0(99999999999) : error C0000: y\nERROR: 0:99999999999: z\n";
    EXPECT_EQ(mapCompilerLog(log, s), log);
}
