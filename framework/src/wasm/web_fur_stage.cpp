#include "web_fur_stage.h"

#include "count_tables.h"
#include "error.h"
#include "function_tables.h"
#include "mesh_shapes.h"
#include "paths.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace raylab {

namespace {

// The geometry-shader budget every OpenGL 3.3 driver offers: the page's
// emulated strand.geom is compiled for it, as native's would be there.
constexpr int kMinOutputVertices = 256;
constexpr int kMinTotalComponents = 1024;

}  // namespace

WebFurStage::WebFurStage(const std::string& stageId, const std::string& lab,
                         const std::string& sceneFile, bool todoMarks)
    : stage_(&findStage(stageId)),
      sources_(lab.empty() ? solutionSources(*stage_) : labSources(*stage_, lab)) {
    const StageInfo& stage = *stage_;
    if (stage.track != "fur") throw Error("stage " + stage.id + " is not a fur stage");
    if (!stage.has("mesh"))
        throw Error(displayPath(stage.folder() / "stage.json") +
                    ": features: a fur stage needs the \"mesh\" feature");
    scene_ = loadFurScene(sceneFile.empty() ? projectRoot() / "assets" / "scenes" / stage.scene
                                            : std::filesystem::path(sceneFile));
    showMesh(0);

    std::vector<std::string> defines = stage.defines();
    if (stage.has("fur_shader")) {
        budget_ = raylab::strandBudget(kMinOutputVertices, kMinTotalComponents,
                                       scene_.fur.strandSegments);
        for (const std::string& d : budget_->defines()) defines.push_back(d);
    }
    if (todoMarks) defines.push_back("RAYLAB_TODO_MARK");  // a check's target, as natively
    const std::vector<std::filesystem::path> search = searchWithVariants(sources_, defines);
    std::set<std::pair<std::string, int>> seen;
    // As GLSL 3.30 (the emulation rewrites that), then for WebGL 2.
    auto assemble330 = [&](const std::string& entry) {
        ShaderSource s = assembleShader(entry, search, defines);
        for (const OpenTodo& t : findOpenTodos(s))
            if (seen.insert({t.file, t.line}).second) todos_.push_back(t);
        return s;
    };
    auto assemble = [&](const std::string& entry) { return asGlslEs300(assemble330(entry)); };
    auto build = [&](const StageProgram& p) {
        WebFurPrograms out;
        const ShaderSource vertex = assemble330(p.vertex);
        out.vertex = asGlslEs300(vertex);
        if (!p.geometry.empty()) {
            out.geometry = emulateGeometryShader(vertex, assemble330(p.geometry));
            out.geometry->expand = asGlslEs300(out.geometry->expand);
            out.geometry->draw = asGlslEs300(out.geometry->draw);
            out.captureFragment = asGlslEs300(captureFragmentShader());
        }
        out.fragment = assemble(p.fragment);
        return out;
    };
    shells_ = {assemble(stage.program.vertex), assemble(stage.program.fragment), {}, {}};
    if (stage.has("fins")) fins_ = build(namedProgram(stage, "fins", "fins"));
    if (stage.has("fur_shader")) strands_ = build(namedProgram(stage, "strands", "fur_shader"));
}

void WebFurStage::showMesh(int furMesh) {
    const std::vector<std::string>& shapes = shapeNames();
    mesh_ = furMesh > 0 && furMesh <= int(shapes.size())
                ? makeShape(shapes[std::size_t(furMesh - 1)],
                            defaultDetail(shapes[std::size_t(furMesh - 1)]))
                : loadFurMesh(scene_);
    const BoundingSphere bounds = boundingSphere(mesh_);
    boundsCentre_ = bounds.centre;
    boundsRadius_ = bounds.radius;
    adjacency_ = stage_->has("fins") ? buildEdgeAdjacency(mesh_) : EdgeAdjacency{};
}

FinCountVerdict WebFurStage::finCount(long emitted, const std::string& view) const {
    CountResult measured;
    measured.measuredOnly = true;
    measured.measured = emitted;
    measured.outOf = long(adjacency_.edgeCount());
    const CountResult r =
        judgedByTable(countTablesAsData(), kTablesAsData, stage_->id, "fin_count", view, measured);
    return {r.passed, r.detail};
}

}  // namespace raylab
