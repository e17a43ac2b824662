#include "stage_programs.h"

#include "bvh.h"
#include "bvh_boxes.h"
#include "error.h"
#include "eye_cells.h"
#include "hidden_tori.h"
#include "light_buffer.h"
#include "paths.h"
#include "scene_baking.h"
#include "shell_slots.h"
#include "triangle_groups.h"

#include <algorithm>
#include <cstdio>

namespace raylab {

namespace {

void checkFits(const Scene& scene, const StageInfo& stage, const char* what, std::size_t count,
               int limit) {
    if (count > 0 && limit == 0)
        throw Error(scene.file + ": " + what + ": stage " + stage.id + " has no " + what);
    if (int(count) > limit)
        throw Error(scene.file + ": " + what + ": " + std::to_string(count) + " " + what +
                    ", but stage " + stage.id + " supports at most " + std::to_string(limit));
}

}  // namespace

void checkSceneFits(const StageInfo& stage, const Scene& scene) {
    const StageLimits& l = stage.limits;
    checkFits(scene, stage, "spheres", scene.spheres.size(), l.spheres);
    checkFits(scene, stage, "materials", scene.materials.size(), l.materials);
    checkFits(scene, stage, "lights", scene.lights.size(), l.lights);
    checkFits(scene, stage, "planes", scene.planes.size(), l.planes);
    checkFits(scene, stage, "discs", scene.discs.size(), l.discs);
    checkFits(scene, stage, "triangles", scene.triangles.size(), l.triangles);
    checkFits(scene, stage, "tori", scene.tori.size(), l.tori);
    checkFits(scene, stage, "mesh triangles", meshTriangleCount(scene), l.meshTriangles);
    checkFits(scene, stage, "textures", scene.textures.size(), l.textures);
    if (scene.skyBox && !l.skyBox) {
        std::string adds;  // the first stage of the track that has one
        for (const StageInfo& s : allStages())
            if (adds.empty() && s.track == stage.track && s.limits.skyBox)
                adds = " (stage " + s.number() + " adds it)";
        throw Error(scene.file + ": sky_box: stage " + stage.id + " has no sky box" + adds);
    }
}

std::vector<std::string> ShaderVariant::defines() const {
    std::vector<std::string> d;
    if (bvh) d.push_back("RAYLAB_BVH");
    if (naiveNumerics) d.push_back("RAYLAB_NAIVE_NUMERICS");
    if (torusClosedForm) d.push_back("TORUS_SOLVER_CLOSED_FORM");
    if (todoMarks) d.push_back("RAYLAB_TODO_MARK");
    if (oldPath) d.push_back("RAYLAB_OLD_PATH");
    if (sharedWork) d.push_back("RAYLAB_SHARED_WORK");
    if (treeAll) d.push_back("RAYLAB_TREE_ALL");
    if (sphereStorage) d.push_back("RAYLAB_SPHERE_STORAGE");
    if (weightCut > 0.0) {
        char value[32];
        std::snprintf(value, sizeof value, "%.9g", weightCut);
        d.push_back(std::string("RAYLAB_WEIGHT_CUT ") + value);
    }
    return d;
}

void ShaderVariant::useDemoLevers() {
    weightCut = kDemoWeightCut;
    sharedWork = true;
    lightBuffer = true;
    eyeCells = true;
    shellSlots = true;
}

bool ShaderVariant::usesLightBuffer(const Scene& scene) const {
    // The old path has its own light_visibility.glsl; tree-all moves the
    // triangles and discs out of testOthers; the naive numerics' fixed ray
    // offset is not covered by the lists' margins.
    return lightBuffer && sharedWork && !oldPath && !treeAll && !naiveNumerics &&
           lightBufferSuits(scene);
}

bool ShaderVariant::usesEyeCells(const Scene& scene) const {
    // The cells replace a walk over spheres only: not without the tree, not
    // with tree-all's triangles and discs in it; the old path is the tracer
    // before the bench's levers.
    return eyeCells && bvh && !treeAll && !oldPath && eyeCellsSuit(scene);
}

bool ShaderVariant::usesShellSlots(const Scene& scene) const {
    // The slots are constants of the specialised program, and the shell's
    // test sits in the shared-work variant's find_closest.glsl; tree-all
    // moves the triangles into the BVH.
    return shellSlots && specialized && sharedWork && !treeAll && !oldPath &&
           hasShellSlots(scene, triangleGroups(scene));
}

std::vector<std::string> ShaderVariant::extensions() const {
    if (sphereStorage) return {"GL_ARB_shader_storage_buffer_object"};
    return {};
}

ShaderVariant ShaderVariant::fastestFor(const Scene& scene) {
    // Measured with `raylab bench` at 800x600, depth 8 (docs/bench/README.md):
    // with 10 spheres the BVH costs more than it saves, with 110
    // it saves a fifth of the frame. Mesh triangles count the same
    // (docs/bench/growth.md: the BVH wins from about a hundred).
    constexpr std::size_t kObjectsForBvh = 32;
    ShaderVariant v;
    v.bvh = scene.spheres.size() + meshTriangleCount(scene) >= kObjectsForBvh;
    v.specialized = true;
    return v;
}

int sphereSlots(const StageInfo& stage, const Scene& scene, const ShaderVariant& variant) {
    if (variant.specialized || variant.sphereStorage) return std::max(1, int(scene.spheres.size()));
    // 64 KB: what llvmpipe and NVIDIA offer, so `raylab shader` prints a
    // program those compile.
    constexpr int kUsualBlockBytes = 65536;
    const int blockBytes = variant.maxBlockBytes > 0 ? variant.maxBlockBytes : kUsualBlockBytes;
    return std::max(1, std::min(stage.limits.spheres, blockBytes / kSphereBlockStride));
}

StagePrograms assembleStagePrograms(const StageInfo& stage, const StageSources& sources,
                                    const Scene& scene, const ShaderVariant& variant,
                                    const std::string& fragmentEntry) {
    // A specialised program sizes its arrays to the scene (the stage's
    // limits are checked by the renderer all the same).
    std::vector<std::string> defines =
        variant.specialized ? bakedSceneDefines(scene) : stage.defines();
    if (variant.specialized)
        for (const std::string& d : stage.extraDefines) defines.push_back(d);
    for (std::string& d : defines)
        if (d.rfind("MAX_SPHERES ", 0) == 0)
            d = "MAX_SPHERES " + std::to_string(sphereSlots(stage, scene, variant));
    for (const std::string& d : variant.defines()) defines.push_back(d);
    // The mesh code (scene_meshes.glsl) only where there are meshes: the
    // other scenes' programs stay short.
    if (!scene.meshes.empty()) defines.push_back("RAYLAB_MESHES");
    if (variant.usesLightBuffer(scene)) {
        defines.push_back("RAYLAB_LIGHT_BUFFER");
        // Shadow rays through the light buffer leave out tori that every
        // shadow ray meets only behind a shell of triangles (hidden_tori.h).
        if (toriHiddenFromLights(scene)) defines.push_back("RAYLAB_TORI_HIDDEN_FROM_LIGHTS");
    }
    // A box-like shell of triangles: a nearest-hit search tests the half of
    // its faces a ray can meet first (shell_slots.h; the constants come
    // with the baked scene).
    if (variant.usesShellSlots(scene)) defines.push_back("RAYLAB_SHELL_SLOTS");
    if (variant.usesEyeCells(scene)) {
        defines.push_back("RAYLAB_EYE_CELLS");
        // Its walk's stack sized to the tree the renderer builds (the same
        // deterministic build): at most one entry per level.
        const Bvh tree = buildBvh(scene, 2, BvhObjects::SpheresAndMeshes);
        defines.push_back("RAYLAB_BVH_STACK_SIZE " + std::to_string(std::max(1, tree.depth)));
        // Its nodes one texel each, after the plain ones (bvh_boxes.h; the
        // renderers append them to the same texture).
        for (const std::string& d : bvhBoxDefines(tree)) defines.push_back(d);
    }
    const std::string prelude =
        variant.specialized ? bakedSceneGlsl(scene, variant.sphereStorage) : std::string();
    std::vector<std::filesystem::path> search = searchWithVariants(sources, defines);
    if (variant.webGl2) search.insert(search.begin(), projectRoot() / "web" / "shaders");
    const std::string& entry = fragmentEntry.empty() ? stage.program.fragment : fragmentEntry;
    StagePrograms p{assembleShader(stage.program.vertex, search, defines, {}, variant.extensions()),
                    assembleShader(entry, search, defines, prelude, variant.extensions())};
    if (variant.webGl2) {
        p.vertex = asGlslEs300(std::move(p.vertex));
        p.fragment = asGlslEs300(std::move(p.fragment));
    }
    return p;
}

}  // namespace raylab
