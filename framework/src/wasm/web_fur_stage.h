#pragma once
// A fur stage as the web page draws it: what the native renderer
// (fur/fur_renderer.cpp) prepares on the CPU, with the same code, for the
// page's WebGL 2 calls (web/src/fur/fur_renderer.ts). The fur scene, its mesh
// and edge adjacency, the bounding sphere, and the programs. WebGL 2 has no
// geometry shaders: the stage's fin.geom and strand.geom run rewritten into
// vertex shaders (core/geometry_emulation.h), fed by the stage's vertex
// shader through transform feedback. Students need not read this file.
#include "adjacency.h"
#include "fin_count.h"
#include "fur_scene.h"
#include "geometry_emulation.h"
#include "mesh.h"
#include "shader_source.h"
#include "stage_catalog.h"
#include "stage_sources.h"
#include "strand_budget.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

struct WebFurPrograms {
    ShaderSource vertex, fragment;
    // With a geometry shader: its emulation (the vertex shader above runs
    // first, captured; this one draws in front of the fragment shader).
    std::optional<EmulatedGeometry> geometry;
    ShaderSource captureFragment;
};

class WebFurStage {
public:
    // LAB: the lab's folder (laid out like labs/), empty for the solution;
    // SCENE: a fur scene file, empty for the stage's own. Throws Error.
    // TODOMARKS: the programs also mark the pixels that reach a TODO stub
    // (a check's second target, RAYLAB_TODO_MARK).
    WebFurStage(const std::string& stage, const std::string& lab, const std::string& scene,
                bool todoMarks = false);

    const StageInfo& stage() const { return *stage_; }
    const FurScene& scene() const { return scene_; }
    const Mesh& mesh() const { return mesh_; }
    const EdgeAdjacency& adjacency() const { return adjacency_; }  // empty without fins
    const WebFurPrograms& shells() const { return shells_; }
    const std::optional<WebFurPrograms>& fins() const { return fins_; }
    const std::optional<WebFurPrograms>& strands() const { return strands_; }
    const std::optional<StrandBudget>& strandBudget() const { return budget_; }
    const std::vector<OpenTodo>& todos() const { return todos_; }
    glm::vec3 boundsCentre() const { return boundsCentre_; }
    // Draws the procedural mesh FURMESH (1..: shapeNames(), at its default
    // detail) instead of the scene's (0), as the native window's key M does
    // (FurRenderer::render): the mesh, adjacency and bounds change.
    void showMesh(int furMesh);
    // The fin count check's verdict on EMITTED fins in the stage's check
    // view VIEW (native: FurRenderer::countCheck), against the count tables
    // of web/function_tables.json (count_tables.h): the core holds no
    // silhouette test. Throws Error when the tables have none for VIEW.
    FinCountVerdict finCount(long emitted, const std::string& view) const;
    float boundsRadius() const { return boundsRadius_; }

private:
    const StageInfo* stage_ = nullptr;
    StageSources sources_;
    FurScene scene_;
    Mesh mesh_;
    EdgeAdjacency adjacency_;
    std::optional<StrandBudget> budget_;
    WebFurPrograms shells_;
    std::optional<WebFurPrograms> fins_, strands_;
    std::vector<OpenTodo> todos_;
    glm::vec3 boundsCentre_{0.0f};
    float boundsRadius_ = 0.0f;
};

}  // namespace raylab
