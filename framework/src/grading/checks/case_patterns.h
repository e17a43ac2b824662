#pragma once
// Reading a function check's verdicts for a diagnosis (function_checks.h):
// which cases failed, picked by their labels. A diagnosis names a cause only
// from a pattern that cause produces (and the catalogue's mistakes are run
// against every diagnosis, so one that fires on another cause fails the
// tests).
#include "function_checks.h"

#include <functional>
#include <string>
#include <vector>

namespace raylab {

using CasePick = std::function<bool(const CaseVerdict&)>;

// Cases whose label starts with PREFIX.
CasePick labelStarts(std::string prefix);
// Cases whose label holds TEXT.
CasePick labelHas(std::string text);
CasePick either(CasePick a, CasePick b);

// Some case that PICK picks failed / none did.
bool anyFailed(const CaseVerdicts& v, const CasePick& pick);
bool noneFailed(const CaseVerdicts& v, const CasePick& pick);
// Every failing case is one PICK picks.
bool onlyFailed(const CaseVerdicts& v, const CasePick& pick);

}  // namespace raylab
