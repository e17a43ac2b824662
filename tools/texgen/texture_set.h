#pragma once
// The list of textures raylab-texgen writes: file names, sizes and the
// generator of each. One list, so that the program, the documentation
// (assets/LICENSES.md) and the regeneration test cannot disagree on it.
#include "image.h"

#include <string>
#include <vector>

namespace raylab::texgen {

struct NamedImage {
    std::string fileName;  // e.g. "earth.png"
    Image image;
};

// Every texture of assets/textures/, computed in memory (deterministic).
std::vector<NamedImage> generateAllTextures();

}  // namespace raylab::texgen
