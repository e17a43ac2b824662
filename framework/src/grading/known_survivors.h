#pragma once
// tests/mutants/<stage>.txt: the mutants of a stage that its checks let
// through, each with the reason, so that a new survivor fails a test while
// the explained ones do not. The format:
//
//     # comment lines and blank lines are skipped
//     intersect_sphere.glsl | if (h < 0.0) return NO_HIT; | "<" -> "<="
//         why: h = 0 is a ray that touches the sphere: the same t either way
//     sphere_uv.glsl | float v = asin(p.y); | "p" -> ...
//         not equivalent: no view looks at the poles
//
// An entry is a mutant's id (mutantId, mutants.h) at the start of a line,
// followed by one indented line that starts with "why:" (an equivalent
// mutant: no picture can tell it from the solution) or "not equivalent:"
// (a real gap in the checks, listed so the lead can add a check).
#include <map>
#include <string>
#include <vector>

namespace raylab {

struct KnownSurvivor {
    std::string reason;       // the indented line, trimmed
    bool equivalent = false;  // "why:"; false for "not equivalent:"
};

// Id -> reason. Throws Error("FILE:LINE: ...") on an entry without its reason,
// a reason without an entry, or an id listed twice.
std::map<std::string, KnownSurvivor> parseKnownSurvivors(const std::string& text,
                                                         const std::string& fileForMessages);

// The SURVIVORS (ids) that KNOWN does not list, in SURVIVORS' order.
std::vector<std::string> unlistedSurvivors(const std::vector<std::string>& survivors,
                                           const std::map<std::string, KnownSurvivor>& known);

}  // namespace raylab
