// Every shader of every available stage (lab and solution, every program,
// geometry shaders included; includes and defines resolved as the framework
// does) passes the Khronos reference compiler for GLSL 3.30 core, so code
// that only one driver accepts is caught.
#include "shader_source.h"
#include "stage_catalog.h"
#include "stage_renderer.h"
#include "stage_sources.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab;
using namespace raylab::test;

namespace {
CommandResult validate(const ScratchDir& dir, const ShaderSource& source, const std::string& name) {
    fs::path file = dir / name;
    writeFile(file, source.text);
    return runCommand("glslangValidator " + quote(file));
}
}  // namespace

TEST(Glslang, EveryStageShaderIsValidGlsl330Core) {
    ASSERT_EQ(runCommand("command -v glslangValidator").exitCode, 0)
        << "install glslang-tools (install.sh --test does)";
    ScratchDir dir;
    int checked = 0;
    for (const StageInfo& stage : allStages()) {
        for (const StageSources& sources :
             {solutionSources(stage), labSources(stage, defaultLabRoot())}) {
            // Every program: the fur track's fins and strands have geometry
            // shaders (whose max_vertices come from the strand budget's defines).
            std::vector<std::string> defines = stage.defines();
            for (const char* d :
                 {"STRAND_SEGMENTS 4", "STRANDS_PER_TRIANGLE 12", "STRAND_MAX_VERTICES 60"})
                defines.push_back(d);
            for (const auto& [key, program] : stage.allPrograms()) {
                SCOPED_TRACE(key);
                const std::pair<std::string, const char*> entries[] = {
                    {program->vertex, "s.vert"},
                    {program->geometry, "s.geom"},
                    {program->fragment, "s.frag"}};
                for (const auto& [entry, name] : entries) {
                    if (entry.empty()) continue;
                    ShaderSource s = assembleShader(entry, sources.search, defines);
                    CommandResult r = validate(dir, s, name);
                    EXPECT_EQ(r.exitCode, 0) << mapCompilerLog(r.out, s);
                    ++checked;
                }
            }
        }
    }
    EXPECT_GE(checked, 4);
    std::printf("[ figure   ] %d shaders valid GLSL 3.30 core\n", checked);
}

// The web build's dialect: every program WebGL 2 can run (every ray-tracing
// stage; the fur track's mesh and shells, not its geometry shaders), lab and
// solution, is valid GLSL ES 3.00 with the ES prelude and web/shaders/ in
// front of the search path - the same files, no per-target copies.
TEST(Glslang, EveryStageCompilesAsGlslEs300ForTheWeb) {
    ScratchDir dir;
    int checked = 0;
    for (const StageInfo& stage : allStages()) {
        std::vector<std::string> defines = stage.defines();
        defines.push_back("RAYLAB_BVH");
        for (const StageSources& sources :
             {solutionSources(stage), labSources(stage, defaultLabRoot())}) {
            SCOPED_TRACE(stage.id + " " + sources.label);
            std::vector<fs::path> search = {sourceDir() / "web/shaders"};
            for (const fs::path& p : searchWithVariants(sources, defines)) search.push_back(p);
            for (const auto& [entry, name] : {std::pair(stage.program.vertex, "s.vert"),
                                              std::pair(stage.program.fragment, "s.frag")}) {
                ShaderSource s = asGlslEs300(assembleShader(entry, search, defines));
                ASSERT_EQ(s.text.rfind("#version 300 es\n", 0), 0u);
                CommandResult r = validate(dir, s, name);
                EXPECT_EQ(r.exitCode, 0) << mapCompilerLog(r.out, s);
                ++checked;
            }
        }
    }
    std::printf("[ figure   ] %d shaders valid GLSL ES 3.00\n", checked);
}

// GLSL ES is stricter (no int -> float conversion); its errors still map to
// the student's file and line through the ES prelude.
TEST(Glslang, EsErrorsMapToTheFileThroughThePrelude) {
    ScratchDir dir;
    writeFile(dir / "s/main.frag",
              "out highp vec4 c;\nvoid main() {\n    float x = 1;\n    c = vec4(x);\n}\n");
    ShaderSource frag = asGlslEs300(assembleShader("main.frag", {dir / "s"}, {}));
    CommandResult r = validate(dir, frag, "bad.frag");
    EXPECT_NE(r.exitCode, 0) << r.all();
    std::string mapped = mapCompilerLog(r.out, frag);
    EXPECT_NE(mapped.find("s/main.frag:3: error:"), std::string::npos) << mapped;
}

// The validator is not a rubber stamp: code Mesa might let through but the
// spec forbids (an implicit int -> float conversion in a return) is rejected,
// and its error maps back to the file and line.
TEST(Glslang, RejectsInvalidCodeAndTheErrorMapsToTheFile) {
    ScratchDir dir;
    writeFile(
        dir / "s/main.frag",
        "out vec4 c;\nfloat f() {\n    return 1.0 + true;\n}\nvoid main() { c = vec4(f()); }\n");
    ShaderSource frag = assembleShader("main.frag", {dir / "s"}, {});
    CommandResult r = validate(dir, frag, "bad.frag");
    EXPECT_NE(r.exitCode, 0) << r.all();
    std::string mapped = mapCompilerLog(r.out, frag);
    EXPECT_NE(mapped.find("s/main.frag:3: error:"), std::string::npos) << mapped;
}
