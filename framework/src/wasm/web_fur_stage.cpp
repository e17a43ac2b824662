#include "web_fur_stage.h"

#include "error.h"
#include "paths.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace raylab {

namespace {

// The geometry-shader budget every OpenGL 3.3 driver offers: the page's
// instanced strands draw as many as native strand.geom would there, so the
// fur looks the same.
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
    mesh_ = loadFurMesh(scene_);
    // The bounding sphere (FurRenderer::setMesh).
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh_.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    boundsCentre_ = 0.5f * (lo + hi);
    for (const glm::vec3& p : mesh_.positions)
        boundsRadius_ = std::max(boundsRadius_, glm::length(p - boundsCentre_));
    if (stage.has("fins")) adjacency_ = buildEdgeAdjacency(mesh_);

    std::vector<std::string> defines = stage.defines();
    if (stage.has("fur_shader")) {
        budget_ = raylab::strandBudget(kMinOutputVertices, kMinTotalComponents,
                                       scene_.fur.strandSegments);
        for (const std::string& d : budget_->defines()) defines.push_back(d);
    }
    if (todoMarks) defines.push_back("RAYLAB_TODO_MARK");  // a check's target, as natively
    std::vector<std::filesystem::path> search = searchWithVariants(sources_, defines);
    search.insert(search.begin(), projectRoot() / "web" / "shaders");
    std::set<std::pair<std::string, int>> seen;
    auto assemble = [&](const std::string& entry) {
        ShaderSource s = asGlslEs300(assembleShader(entry, search, defines));
        for (const OpenTodo& t : findOpenTodos(s))
            if (seen.insert({t.file, t.line}).second) todos_.push_back(t);
        return s;
    };
    shells_ = {assemble(stage.program.vertex), assemble(stage.program.fragment)};
    if (stage.has("fins")) {
        const StageProgram& p = namedProgram(stage, "fins", "fins");
        fins_ = WebFurPrograms{assemble("fin_instanced.vert"), assemble(p.fragment)};
        assemble(p.vertex);  // for its TODOs only
        if (!p.geometry.empty()) assemble(p.geometry);
    }
    if (stage.has("fur_shader")) {
        const StageProgram& p = namedProgram(stage, "strands", "fur_shader");
        strands_ = WebFurPrograms{assemble("strand_instanced.vert"), assemble(p.fragment)};
        if (!p.geometry.empty()) assemble(p.geometry);
    }
}

}  // namespace raylab
