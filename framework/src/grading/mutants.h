#pragma once
// Single-token mutants of the code students write (the //@solution regions of
// a solution file), for `raylab mutants`: each is the solution with one
// token changed the way a student's slip would change it. A mutant the
// grader does not catch shows a skill the checks do not test (or is
// equivalent: no picture can tell it from the solution).
//
// Operators, in this order on each token: comparisons (< <= > >= swapped for
// the other strictness and the other direction, == <-> !=), arithmetic
// (binary + <-> -, * <-> /, and their assignments), && <-> ||, min <-> max,
// normalize( dropped, a unary minus dropped, a nonzero number set to zero.
// Comments and preprocessor lines are never mutated.
#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

struct Mutant {
    std::string file;        // the file's name, e.g. "intersect_sphere.glsl"
    int line = 0;            // 1-based, in the marked solution file
    std::size_t column = 0;  // 0-based byte offset of the replaced text in that line
    std::size_t length = 0;  // bytes replaced
    std::string replacement;
    // How it reads in reports and survivor lists: the original line's code
    // (comment stripped, white space folded), the change ("<" -> "<=") and
    // the occurrence: the n-th mutant of the file with the same line text and
    // change (1 for almost all). Nothing here depends on line numbers, so a
    // mutant keeps its name when lines above it are edited.
    std::string lineText;
    std::string from, to;
    int occurrence = 1;
};

// Every mutant of the solution lines of TEXT (a marked solution file named
// FILE), in the order of the file: by line, then column, then operator.
std::vector<Mutant> generateMutants(const std::string& file, const std::string& text);

// TEXT with M applied (M must come from generateMutants of TEXT).
std::string applyMutant(const std::string& text, const Mutant& m);

// "intersect_sphere.glsl | if (h < 0.0) return NO_HIT; | \"<\" -> \"<=\"",
// with " #N" after the change when the occurrence N is above 1.
std::string mutantId(const Mutant& m);

// At most MAX of ALL (0: all), picked by SEED, deterministic on every
// platform, in ALL's order.
std::vector<Mutant> sampleMutants(const std::vector<Mutant>& all, std::size_t max,
                                  std::uint32_t seed);

}  // namespace raylab
