// `raylab shader`: prints the GLSL a ray-tracing stage's program is compiled
// from, assembled exactly as the renderer assembles it (includes resolved,
// defines, the baked scene). `--es` prints the GLSL ES 3.00 the web build
// compiles; its tests compare the page's own assembly with this. `--function
// NAME` prints the harness program of that function check instead.
#include "command.h"
#include "command_options.h"
#include "error.h"
#include "harness_program.h"
#include "scene_transform.h"
#include "stage_programs.h"
#include "track_registry.h"

#include <cstdio>

namespace raylab {

namespace {

struct ShaderOptions {
    StageOptions stage;
    bool vertex = false;
    bool es = false;
    bool generic = false;
    bool noBvh = false;
    bool origins = false;
    bool demo = false;
    std::string function;
};

// The harness program of the function check NAME, one of STAGE's.
StagePrograms harnessPrograms(const std::string& name, const StageSetup& setup, bool es) {
    const FunctionSpec& spec = functionSpec(name);  // throws for an unknown name
    bool checked = false;
    for (const FunctionSpec* s : functionSpecsFor(*setup.stage)) checked = checked || s == &spec;
    if (!checked)
        throw Error("--function " + name + ": stage " + setup.stage->id +
                    " does not check it (stage " + stageCheckingFunction(name).id + " does)");
    HarnessProgram h = assembleHarness(spec, *setup.stage, setup.sources, {}, es);
    return {h.vertex, h.fragment};
}

int printSource(const StagePrograms& programs, const ShaderOptions& o);

int cmdShader(const ShaderOptions& o) {
    StageSetup setup = resolveStageOptions(o.stage);
    if (!o.function.empty()) {
        if (o.demo || o.generic || o.noBvh)
            throw Error("--function: the harness program takes no --demo, --generic or --no-bvh");
        return printSource(harnessPrograms(o.function, setup, o.es), o);
    }
    requireRayTracingStage(*setup.stage, "raylab shader");
    // The scene in the frame the renderer draws it in (scene_transform.h):
    // the numbers its program holds.
    const Scene scene = transformScene(setup.scene, sceneFrame(setup.scene));
    ShaderVariant variant = ShaderVariant::fastestFor(scene);
    variant.specialized = !o.generic;
    if (o.noBvh) variant.bvh = false;
    variant.webGl2 = o.es;
    if (o.demo) {
        if (setup.sources.lab)
            throw Error("--demo: the demo's levers replace files students write: only for the "
                        "solution (add --solution)");
        variant.useDemoLevers();
    }
    return printSource(assembleStagePrograms(*setup.stage, setup.sources, scene, variant), o);
}

int printSource(const StagePrograms& programs, const ShaderOptions& o) {
    const ShaderSource& source = o.vertex ? programs.vertex : programs.fragment;
    if (!o.origins) {
        std::fputs(source.text.c_str(), stdout);
        return 0;
    }
    // One line per assembled line: where it came from, a tab, the text.
    std::size_t start = 0;
    for (const SourceLine& from : source.origin) {
        std::size_t end = source.text.find('\n', start);
        std::printf("%s:%d\t%s\n", from.file.c_str(), from.line,
                    source.text.substr(start, end - start).c_str());
        start = end + 1;
    }
    return 0;
}

}  // namespace

Command shaderCommand() {
    return {
        "shader",
        "print the GLSL a ray-tracing stage is compiled from (includes resolved, the scene "
        "compiled in; --es: as the web build compiles it)",
        [](CLI::App& cmd) {
            auto o = std::make_shared<ShaderOptions>();
            CLI::Option* lab = addStageOptions(cmd, o->stage, false);
            cmd.add_flag("--vertex", o->vertex, "the vertex shader instead of the fragment shader");
            cmd.add_flag(
                "--es", o->es,
                "the web page's program: GLSL ES 3.00, web/shaders first on the search path");
            cmd.add_flag("--generic", o->generic,
                         "the stage's generic program (scene in uniforms) instead of the "
                         "program specialised to the scene");
            cmd.add_flag("--no-bvh", o->noBvh, "stage 08: the linear search instead of the BVH");
            cmd.add_flag("--demo", o->demo,
                         "the program raylab demo draws: the solution with the demo's levers "
                         "(weight cut, shared work, light buffer, eye cells)");
            cmd.add_option("--function", o->function,
                           "the harness program of this function check of the stage (e.g. "
                           "intersectSphere), as raylab check and the page compile it");
            cmd.add_flag("--origins", o->origins,
                         "prefix every line with the file:line it came from");
            return std::function<int()>([=] {
                o->stage.labGiven = lab->count() > 0;
                return cmdShader(*o);
            });
        }};
}

}  // namespace raylab
