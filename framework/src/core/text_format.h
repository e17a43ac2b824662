#pragma once
// Numbers as text: the framework's one place for number formatting. All of
// it is locale-free ('.' as the decimal point whatever the user's locale).
#include <string>

namespace raylab {

// DIGITS significant digits, printf's %g: "0.000123", "1.5e+30".
std::string significant(double v, int digits);

// DECIMALS digits after the point, printf's %f: "3.140".
std::string fixedPoint(double v, int decimals);

// At most DECIMALS digits after the point, without trailing zeros: "87.5", "100".
std::string trimmedFixed(double v, int decimals);

// A wall time: "4.2 s", "3 min 07 s", "1 h 02 min" (0 for NaN or negative).
std::string durationText(double seconds);

// The shortest text that reads back as exactly V ("0.1", "1e-07").
std::string shortestExact(double v);
// The same text without std::to_chars (the WebAssembly core's libc++ lacks
// it for floating point): the fewest digits that read back, written fixed or
// scientific, whichever is shorter (fixed on a tie), as to_chars writes them.
std::string shortestExactPortable(double v);

}  // namespace raylab
