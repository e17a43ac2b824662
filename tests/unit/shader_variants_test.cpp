// A variant file (framework/shaders/variants/) replaces a solution file for
// one configuration; it must stay the original plus its one intended change,
// or a fix made to the original silently goes missing there (it happened:
// the meshes variant of surfaceAt lost the hit points' re-projection).
#include "paths.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace raylab;

namespace {

// The file's lines after its leading comment block, without the lines that
// contain any of DROP.
std::vector<std::string> codeLines(const fs::path& file, const std::vector<std::string>& drop) {
    std::istringstream in(test::readFile(file));
    std::vector<std::string> lines;
    bool header = true;
    for (std::string line; std::getline(in, line);) {
        if (header && line.rfind("//", 0) == 0) continue;
        header = false;
        bool dropped = false;
        for (const std::string& d : drop) dropped = dropped || line.find(d) != std::string::npos;
        if (!dropped) lines.push_back(line);
    }
    return lines;
}

}  // namespace

TEST(ShaderVariants, MeshesSurfaceAtIsTheOriginalPlusMeshes) {
    const fs::path root = projectRoot();
    const auto original = codeLines(root / "solution/05-primitives/surface_at.glsl", {});
    const auto variant = codeLines(
        root / "framework/shaders/variants/meshes/08-full/surface_at.glsl", {"kind == KIND_MESH"});
    EXPECT_EQ(variant, original);
    // And the comparison can fail: the variant without its mesh line dropped.
    EXPECT_NE(codeLines(root / "framework/shaders/variants/meshes/08-full/surface_at.glsl", {}),
              original);
}
