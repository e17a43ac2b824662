// `raylab shader`: prints the GLSL a stage's program is compiled from,
// assembled exactly as the renderer assembles it (includes resolved, defines,
// the baked scene for the ray tracer; for the fur track one of the stage's
// programs, shells, fins or strands, with its geometry shader). `--es`
// prints the GLSL ES 3.00 the web build compiles; its tests compare the
// page's own assembly with this. `--function NAME` prints the harness program
// of that function check instead.
#include "command.h"
#include "command_options.h"
#include "error.h"
#include "function_tables.h"
#include "fur_renderer.h"
#include "fur_scene.h"
#include "gl_context.h"
#include "harness_program.h"
#include "scene_transform.h"
#include "stage_programs.h"
#include "stage_sources.h"
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
    bool geometry = false;
    std::string program;
    std::string function;
};

// A fur stage's program NAME ("shells", or one of stage.json's "programs")
// assembled as fur_renderer.cpp assembles it: the stage's defines, and for
// the fur shader the strand budget of this machine's driver.
StagePrograms furPrograms(const StageSetup& setup, const ShaderOptions& o) {
    const StageInfo& stage = *setup.stage;
    std::string names = "shells";
    for (const auto& [name, p] : stage.programs) names += ", " + name;
    const std::string name = o.program.empty() ? "shells" : o.program;
    if (name != "shells" && !stage.programs.count(name))
        throw Error("--program " + name + ": stage " + stage.id + " has the programs " + names);
    const StageProgram& p = name == "shells" ? stage.program : stage.programs.at(name);
    if (o.geometry && p.geometry.empty())
        throw Error("--geometry: the " + name + " program of stage " + stage.id +
                    " has no geometry shader (" + names + ")");
    std::vector<std::string> defines = stage.defines();
    if (p.geometry == "strand.geom") {
        // How many strand points a geometry shader may emit is the driver's.
        auto context = createHeadlessContext(Backend::Auto);
        for (const std::string& d :
             driverStrandBudget(loadFurScene(setup.sceneFile).fur.strandSegments).defines())
            defines.push_back(d);
    }
    const auto search = searchWithVariants(setup.sources, defines);
    const std::string& entry = o.geometry ? p.geometry : o.vertex ? p.vertex : p.fragment;
    ShaderSource source = assembleShader(entry, search, defines);
    if (o.es) source = asGlslEs300(std::move(source));
    return {source, source};  // the one shader asked for: printSource prints either
}

// The harness program of the function check NAME, one of STAGE's.
StagePrograms harnessPrograms(const std::string& name, const StageSetup& setup, bool es) {
    const FunctionSpec& spec = functionSpec(name);  // throws for an unknown name
    bool checked = false;
    for (const FunctionSpec* s : functionSpecsFor(*setup.stage)) checked = checked || s == &spec;
    if (!checked)
        throw Error("--function " + name + ": stage " + setup.stage->id +
                    " does not check it (stage " + stageCheckingFunction(name).id + " does)");
#ifdef RAYLAB_STUDENT_BUILD  // the harness GLSL is data here (function_tables.h)
    HarnessProgram h = assembleHarness(withHarnessFrom(tablesAsData(), spec, kTablesAsData),
                                       *setup.stage, setup.sources, {}, es);
#else
    HarnessProgram h = assembleHarness(spec, *setup.stage, setup.sources, {}, es);
#endif
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
    if (setup.stage->track == "fur") {
        if (o.demo || o.generic || o.noBvh)
            throw Error("--demo, --generic and --no-bvh are for the ray-tracing stages");
        if (o.es && o.geometry)
            throw Error("--es --geometry: WebGL 2 has no geometry shaders (the page draws fins "
                        "and strands with instanced vertex shaders)");
        return printSource(furPrograms(setup, o), o);
    }
    if (o.geometry || !o.program.empty())
        throw Error("--geometry and --program are for the fur stages (" + setup.stage->id +
                    " has one program: its vertex and fragment shaders)");
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
        "print the GLSL a stage is compiled from (includes resolved, the defines, the scene "
        "compiled in; --es: as the web build compiles it): every type, uniform and helper your "
        "files can use",
        [](CLI::App& cmd) {
            auto o = std::make_shared<ShaderOptions>();
            CLI::Option* lab = addStageOptions(cmd, o->stage, false);
            cmd.add_flag("--vertex", o->vertex, "the vertex shader instead of the fragment shader");
            cmd.add_flag("--geometry", o->geometry,
                         "fur stages: the geometry shader of the program (fin.geom, strand.geom)");
            cmd.add_option("--program", o->program,
                           "fur stages: which program: shells (default), fins or strands");
            cmd.add_flag(
                "--es", o->es,
                "the web page's program: GLSL ES 3.00, web/shaders first on the search path");
            cmd.add_flag("--generic", o->generic,
                         "the stage's generic program (scene in uniforms) instead of the "
                         "program specialised to the scene");
            cmd.add_flag("--no-bvh", o->noBvh, "stage 08: the linear search instead of the BVH");
#ifndef RAYLAB_STUDENT_BUILD  // the demo's program is the solution's
            cmd.add_flag("--demo", o->demo,
                         "the program raylab demo draws: the solution with the demo's levers "
                         "(weight cut, shared work, light buffer, eye cells)");
#endif
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
