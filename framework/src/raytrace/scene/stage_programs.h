#pragma once
// How a ray-tracing stage's program is assembled from its files: the defines
// (the stage's limits, or the scene's own sizes when specialised), the
// variant switches, the baked scene prelude and the search path with the
// variant folders. One place, shared by the renderer (stage_renderer.cpp)
// and `raylab shader` (which prints what the web build must reproduce).
#include "scene.h"
#include "shader_source.h"
#include "stage_catalog.h"
#include "stage_sources.h"

#include <string>
#include <vector>

namespace raylab {

// Bytes one sphere takes in each of the spheres' uniform blocks (std140
// array stride; raytrace/sphere_blocks.h fills them).
constexpr int kSphereBlockStride = 16;

// How the stage's shader is compiled (fixed per program, unlike RenderSettings).
// `raylab bench` compares the choices; the defaults are the fastest correct ones.
struct ShaderVariant {
    bool bvh = true;           // RAYLAB_BVH: stage 08 finds bounded objects through a BVH (bvh.h)
    bool specialized = false;  // the scene's static data compiled in as constants (scene_baking.h)
    bool naiveNumerics = false;    // RAYLAB_NAIVE_NUMERICS: the textbook methods of tests/numerics
    bool torusClosedForm = false;  // TORUS_SOLVER_CLOSED_FORM: the seed's torus solver
    bool todoMarks = false;        // RAYLAB_TODO_MARK: also mark the pixels that reach a TODO stub
    // RAYLAB_WEIGHT_CUT (when > 0): reflected and refracted rays whose
    // weight is below this in every channel are not traced (a bench lever:
    // framework/shaders/variants/weight-cut).
    double weightCut = 0.0;
    // The cut `raylab demo` uses: one 8-bit step. Measured with `raylab
    // bench` on pro: RMSE against the reference unchanged to 2 digits
    // (0.00035 -> 0.00036), frame time -20% (docs/bench/README.md).
    static constexpr double kDemoWeightCut = 1.0 / 255.0;
    // RAYLAB_OLD_PATH: the tracer before the bench's levers: glow.glsl casts
    // a blocker ray for every pixel in front of the sun, halo or not, and
    // light_visibility.glsl a shadow ray toward lights behind the surface.
    bool oldPath = false;
    // RAYLAB_SHARED_WORK: the same picture with less work (variants/shared-
    // work): the glow reuses the primary ray's hit instead of searching
    // again, and shading visits only the lights in front of the surface.
    // On in `raylab demo` and the window whenever they show the solution.
    bool sharedWork = false;
    // RAYLAB_LIGHT_BUFFER: shadow rays find the spheres that may block them
    // in a light buffer (scene/light_buffer.h) instead of walking the BVH;
    // the same picture. Where the scene suits it (lightBufferSuits) and not
    // with oldPath, treeAll or naiveNumerics. On with the demo's levers.
    // Its shadow rays also skip tori no light can see (hidden_tori.h:
    // RAYLAB_TORI_HIDDEN_FROM_LIGHTS). Only with sharedWork, whose triangle
    // shear its shadow rays use.
    bool lightBuffer = false;
    // RAYLAB_EYE_CELLS: primary rays find the spheres they may meet in the
    // eye's cells (scene/eye_cells.h) instead of walking the BVH from its
    // root; the same picture. Where the scene suits it (eyeCellsSuit) and
    // the program walks a BVH of spheres (not with oldPath or treeAll). On
    // with the demo's levers.
    bool eyeCells = false;
    // RAYLAB_SHELL_SLOTS: in the specialised program with shared work, a
    // group of the scene's triangles that is a box-like shell has its
    // nearest-hit searches test only the faces a ray can meet it on first
    // (scene/shell_slots.h); the same picture. On with the demo's levers.
    bool shellSlots = false;
    // RAYLAB_TREE_ALL: stage 08's BVH also holds the scene file's triangles
    // and discs (the bench's tree-all row; bvh.h says why it is not the default).
    bool treeAll = false;
    // The device's GL_MAX_UNIFORM_BLOCK_SIZE (the renderer sets it): a
    // generic program declares no more spheres (MAX_SPHERES) than one of its
    // blocks holds. 0: no device (`raylab shader`): the stage's limit.
    int maxBlockBytes = 0;
    // RAYLAB_SPHERE_STORAGE: the spheres' arrays are storage blocks (OpenGL
    // 4.3). The renderer sets it for more spheres than a uniform block holds
    // (sphere_blocks.h); set beforehand, it asks for them anyway (the growth
    // bench compares the two).
    bool sphereStorage = false;
    // The web page's program (web/README.md): GLSL ES 3.00, with web/shaders
    // first on the search path (its files read 2D textures where WebGL 2
    // has no buffer textures). `raylab shader --es` prints it.
    bool webGl2 = false;
    // Switches on the levers of `raylab demo` and of the window showing the
    // solution: the weight cut (kDemoWeightCut), shared work, the light
    // buffer, the eye's cells and the shells' slots. Only for
    // the solution: their variant files replace files students write.
    void useDemoLevers();
    std::vector<std::string> defines() const;  // the defines for the switches above
    // Whether a program for SCENE gets RAYLAB_LIGHT_BUFFER (see lightBuffer).
    bool usesLightBuffer(const Scene& scene) const;
    // Whether a program for SCENE gets RAYLAB_SHELL_SLOTS (see shellSlots).
    bool usesShellSlots(const Scene& scene) const;
    // Whether a program for SCENE gets RAYLAB_EYE_CELLS (see eyeCells).
    bool usesEyeCells(const Scene& scene) const;
    std::vector<std::string> extensions() const;  // the GLSL extensions they need

    // The fastest correct choice for SCENE on llvmpipe (`raylab bench`): the
    // scene compiled in, and the BVH only where there are enough spheres to
    // repay walking it (lite's 10 are found faster by the plain loop).
    static ShaderVariant fastestFor(const Scene& scene);
};

// Throws Error (one line: the scene file, what, how many, the stage's
// limit) when SCENE has more of something than STAGE supports.
void checkSceneFits(const StageInfo& stage, const Scene& scene);

struct StagePrograms {
    ShaderSource vertex;
    ShaderSource fragment;
};

// The length of the sphere arrays (MAX_SPHERES, scene_spheres.glsl): the
// scene's count in a specialised program, else the stage's limit, capped
// by the device's uniform blocks (ShaderVariant::maxBlockBytes, or 64 KB
// where no device is known); at least 1. Storage blocks have no declared
// length; their buffers hold the scene's spheres.
int sphereSlots(const StageInfo& stage, const Scene& scene, const ShaderVariant& variant);

// FRAGMENTENTRY: the entry fragment shader; empty for the stage's own.
// Throws Error for a missing or forbidden #include.
StagePrograms assembleStagePrograms(const StageInfo& stage, const StageSources& sources,
                                    const Scene& scene, const ShaderVariant& variant,
                                    const std::string& fragmentEntry = "");

}  // namespace raylab
