// Runs a function check on the GPU: a one-row float framebuffer, one pixel
// per case; the harness fragment shader reads the case's inputs from a float
// texture, calls the student's function and writes its result.
#include "function_harness.h"
#include "canvas.h"
#include "error.h"
#include "framebuffer.h"
#include "function_tables.h"
#include "harness_program.h"
#include "shader_program.h"

#include <new>

namespace raylab {

namespace {

class CaseTexture {
public:
    explicit CaseTexture(const FunctionSpec& spec) {
        const int n = int(spec.cases.size());
        const std::vector<float> texels = harnessCaseTexels(spec);
        glGenTextures(1, &id_);
        glBindTexture(GL_TEXTURE_2D, id_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, n, 4, 0, GL_RGBA, GL_FLOAT, texels.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    ~CaseTexture() { glDeleteTextures(1, &id_); }
    CaseTexture(const CaseTexture&) = delete;
    CaseTexture& operator=(const CaseTexture&) = delete;
    GLuint id() const { return id_; }

private:
    GLuint id_ = 0;
};

}  // namespace

std::vector<glm::vec4> runHarness(const FunctionSpec& spec, const StageInfo& stage,
                                  const StageSources& sources,
                                  const std::vector<std::string>& extraDefines) {
    const HarnessProgram harness = assembleHarness(spec, stage, sources, extraDefines);
    ShaderProgram program(harness.vertex, harness.fragment);

    const int n = int(spec.cases.size());
    CaseTexture cases(spec);
    Framebuffer target(n, 1, PixelFormat::Rgba32F);
    Canvas canvas;
    target.bind();
    program.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, cases.id());
    glUniform1i(program.uniform("uCases"), 0);
    if (!harnessDrawsPerCase(spec)) {
        canvas.draw();
    } else {  // each case with its own uniforms: one pixel at a time
        glEnable(GL_SCISSOR_TEST);
        for (int i = 0; i < n; ++i) {
            for (const auto& [name, value] : spec.cases[std::size_t(i)].uniforms)
                glUniform1i(program.uniform(name), value);
            glScissor(i, 0, 1, 1);
            canvas.draw();
        }
        glDisable(GL_SCISSOR_TEST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::vector<float> raw = target.readFloats();
    std::vector<glm::vec4> results;
    for (int i = 0; i < n; ++i)
        results.emplace_back(raw[std::size_t(i) * 4], raw[std::size_t(i) * 4 + 1],
                             raw[std::size_t(i) * 4 + 2], raw[std::size_t(i) * 4 + 3]);
    return results;
}

FunctionOutcome runFunctionCheck(const FunctionSpec& checked, const StageInfo& stage,
                                 const StageSources& sources) {
#ifdef RAYLAB_STUDENT_BUILD
    // No references or stand-ins here: the harness GLSL and the expected
    // values come from the repository's tables (function_tables.h).
    const FunctionSpec spec = withHarnessFrom(tablesAsData(), checked, kTablesAsData);
    const std::vector<glm::dvec4> wants = tableOf(tablesAsData(), spec.name, kTablesAsData).wants;
#else
    const FunctionSpec& spec = checked;
#endif
    std::vector<glm::vec4> results;
    try {
        results = runHarness(spec, stage, sources);
    } catch (const std::bad_alloc&) {
        throw;  // the process's memory is gone: grading reports "out of memory" (cmd_grade_item)
    } catch (
        const std::exception& e) {  // Error or ShaderError: the student's code does not compile
        FunctionOutcome out;
        out.name = spec.name;
        out.total = int(spec.cases.size());
        out.compiled = false;
        out.firstFailure = std::string("does not compile: ") + e.what();
        return out;
    }
#ifdef RAYLAB_STUDENT_BUILD
    return scoreFunctionResults(spec, results, wants);
#else
    return scoreFunctionResults(spec, results);
#endif
}

std::vector<EarlierFailure> runEarlierFunctionChecks(const StageInfo& stage,
                                                     const StageSources& sources) {
    std::vector<EarlierFailure> failures;
    for (const EarlierFunctionCheck& check : earlierFunctionChecks(stage, sources)) {
#ifdef RAYLAB_STUDENT_BUILD
        // An earlier stage the repository does not release has no table.
        if (!tablesAsData().count(check.spec->name)) continue;
#endif
        // The earlier stage as the student's folders draw it.
        const StageSources own =
            labSources(*check.stage, sources.labRoot, MissingLabFiles::FromHandedOutLab);
        FunctionOutcome outcome = runFunctionCheck(*check.spec, *check.stage, own);
        if (outcome.passed != outcome.total) failures.push_back({check, outcome});
    }
    return failures;
}

}  // namespace raylab
