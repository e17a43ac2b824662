#pragma once
// How the fur and growth benches' reports write a measured number: in the
// CSV the shortest exact text (an empty cell for a figure not measured), in
// the Markdown tables 3 significant digits ("-" for none).
#include "text_format.h"

#include <cmath>
#include <string>

namespace raylab {

inline std::string measuredCsv(double x) { return std::isfinite(x) ? shortestExact(x) : ""; }
inline std::string measuredMs(double v) { return std::isfinite(v) ? significant(v, 3) : "-"; }

}  // namespace raylab
