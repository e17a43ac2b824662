#pragma once
// Where the RayLab tree (framework/, solution/, labs/, assets/) lives, found
// the same way whatever directory the program is started from.
#include <filesystem>
#include <string>

namespace raylab {

namespace fs = std::filesystem;

// Order: $RAYLAB_ROOT, then the first parent of the executable that holds
// framework/shaders, then the source tree the binary was built from.
const fs::path& projectRoot();

// A path for messages: relative to the project root when inside it, so that
// errors read "labs/01-raycast/intersect_sphere.glsl:12" rather than a long
// absolute path; otherwise unchanged.
std::string displayPath(const fs::path& p);

// This program's own executable (/proc/self/exe). Throws Error.
fs::path executablePath();

// Reads a whole text file; throws Error("cannot read FILE: reason").
std::string readTextFile(const fs::path& p);

}  // namespace raylab
