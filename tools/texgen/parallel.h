#pragma once
// Rows of a texture computed on all cores. Every pixel is a pure function of
// its position, and each row is written by exactly one thread, so the result
// is bit-identical to a serial loop whatever the number of threads; only the
// time changes (the regeneration test runs the whole generator).
#include <functional>

namespace raylab::texgen {

// Calls ROW(y) once for every y in [0, rows), spread over the hardware threads.
void forEachRow(int rows, const std::function<void(int)>& row);

}  // namespace raylab::texgen
