#pragma once
// A failure the user can act on. Its message is one line that names the cause
// (a file, a flag, a shader line); main() prints it and exits non-zero.
#include <stdexcept>
#include <string>

namespace raylab {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace raylab
