#pragma once
// Function checks: a stage's GLSL functions run on a table of inputs in a
// small harness shader, compared with a double-precision C++ version of the
// same function. The tables include the hard cases (tangent rays, rays that
// start on the surface, parallel rays, hits from inside) and invariants (unit
// normals, Fresnel weights within [0, 1], no NaN). Used by `raylab check`,
// `raylab grade` and the page. This module needs no GL: the harness program
// is assembled in harness_program.h, run on a GPU by grading/function_harness.h
// (native) or the page (WebGL 2).
#include "stage_catalog.h"

#include <glm/glm.hpp>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

// One row of inputs: up to four vec4s, a0..a3 in the harness.
struct FunctionCase {
    std::string label;  // "tangent ray", "from inside"
    std::array<glm::dvec4, 4> in{};
    bool hitOrMiss =
        false;  // on the boundary: either answer is right (if a hit, its t must be right)
    // Integer uniforms the checked code reads (uColorMode, uShadows), set
    // for this case alone; a case with any is drawn on its own.
    std::vector<std::pair<std::string, int>> uniforms;
};

// What a case's result was, for a diagnosis to read.
struct CaseVerdict {
    const FunctionCase* input = nullptr;
    glm::dvec4 got{0.0}, want{0.0};
    bool failed = false;
};
using CaseVerdicts = std::vector<CaseVerdict>;  // every case's, in the spec's order

// A cause that the pattern of failing cases proves, not a guess: e.g. "only
// rays leaving the glass refract wrong, and entering ones are right" is what
// an eta that is not inverted gives. The first diagnosis of a spec that
// applies is printed under the function's FAIL line; the mistakes catalogue
// says which diagnoses each mistake must get (its "hints", by ID), so a
// diagnosis that names a cause a mistake does not have fails the tests.
struct FunctionDiagnosis {
    std::string id;     // "eta", unique within the spec: "refractGlass:eta" in the catalogue
    std::string cause;  // what the student reads
    // True when the verdicts (at least one failed) show this cause.
    std::function<bool(const CaseVerdicts&)> applies;
};

struct FunctionSpec {
    std::string name;                   // the GLSL function, e.g. "intersectSphere"
    std::vector<std::string> includes;  // harness includes after lab_todo.glsl
    std::string call;                   // GLSL expression: a vec4 from a0..a3
    // GLSL before the includes: stand-ins for what the scene would provide
    // (plain globals in place of the light and sphere uniforms, a texture
    // lookup), set by HELPERS from the case's inputs.
    std::string prelude;
    std::string helpers;  // GLSL after the includes, for CALL to use
    // Defines the harness adds to the stage's (RAYLAB_BVH: the BVH's walk,
    // not the linear search the framework substitutes without it).
    std::vector<std::string> defines;
    std::vector<FunctionCase> cases;
    std::function<glm::dvec4(const FunctionCase&)> reference;
    // Empty when GOT agrees with WANT, else one line saying how it does not.
    std::function<std::string(const FunctionCase&, const glm::dvec4& got, const glm::dvec4& want)>
        compare;
    std::vector<FunctionDiagnosis> diagnoses;  // in order: the first that applies is printed
};

// A spec's double-precision reference: `RAYLAB_REFERENCE(s, lambda);`. The
// page's WebAssembly core is built with RAYLAB_REFERENCES_AS_DATA: without
// them (nothing of the reference module is linked, so no solution code
// reaches students in raylab_core.js); it scores against the expected values
// shipped as data (web/function_tables.json, function_tables.h).
// RAYLAB_REFERENCE_FUNCTION(f): a reference passed as an argument.
// A spec's harness GLSL (prelude, helpers): `s.prelude =
// RAYLAB_HARNESS_GLSL("...")`. The stand-ins in it can come close to a
// stage's answer (a loop over the spheres that keeps the nearest hit is
// stand-in for find_closest.glsl in a later stage's check), so the page's
// core leaves them out too and reads them from the tables, which a bundle
// holds for its released stages only (function_tables.h).
#ifdef RAYLAB_REFERENCES_AS_DATA
#define RAYLAB_HARNESS_GLSL(...) std::string()
#define RAYLAB_REFERENCE(spec, ...) ((void)(spec))
#define RAYLAB_REFERENCE_FUNCTION(...) nullptr
#else
#define RAYLAB_HARNESS_GLSL(...) std::string(__VA_ARGS__)
#define RAYLAB_REFERENCE(spec, ...) ((spec).reference = __VA_ARGS__)
#define RAYLAB_REFERENCE_FUNCTION(...) __VA_ARGS__
#endif

// Every checked function. A stage runs those its stage.json lists under
// "function_checks" (by name).
const std::vector<FunctionSpec>& functionSpecs();
const FunctionSpec& functionSpec(const std::string& name);  // throws Error for an unknown name
// Throws Error naming the stage.json and key for an unknown name.
std::vector<const FunctionSpec*> functionSpecsFor(const StageInfo& stage);
// The stage whose TODO writes function NAME (the one that lists it).
const StageInfo& stageCheckingFunction(const std::string& name);

struct FunctionOutcome {
    std::string name;
    int passed = 0, total = 0;
    std::string firstFailure;  // "tangent ray: expected t = 5, got no hit"
    bool compiled = true;      // false: the harness did not compile (message in firstFailure)
    std::string cause;         // the text of the diagnosis that applies, or empty
};

// What a harness run wrote: one vec4 per case, w = kHarnessTodoMarker when
// the call reached a labTodo() stub (every checked call otherwise writes 1
// there): a stub's answer never earns credit, even where it happens to be
// right (NO_HIT for a ray that misses).
inline constexpr float kHarnessTodoMarker = -12345.0f;

// Judges RESULTS (one per case of SPEC, as the harness wrote them) against
// WANTS (the reference's value for each case): native's GL run and the
// page's WebGL run are scored by this one function.
FunctionOutcome scoreFunctionResults(const FunctionSpec& spec,
                                     const std::vector<glm::vec4>& results,
                                     const std::vector<glm::dvec4>& wants);
// The reference's value for every case of SPEC (native builds only; throws
// Error in the page's core, which reads them from function_tables.h).
std::vector<glm::dvec4> referenceWants(const FunctionSpec& spec);
// Scored against referenceWants(SPEC).
FunctionOutcome scoreFunctionResults(const FunctionSpec& spec,
                                     const std::vector<glm::vec4>& results);

}  // namespace raylab
