#pragma once
// One text field of a CSV file (RFC 4180), shared by the grade and bench
// reports: quoted when it holds a comma, quote or line break, and with a
// leading apostrophe when a spreadsheet would run it as a formula (=, +, -,
// @, tab, CR first) - a student's folder or a scene's name must not compute.
#include <string>

namespace raylab {

std::string csvText(const std::string& raw);

}  // namespace raylab
