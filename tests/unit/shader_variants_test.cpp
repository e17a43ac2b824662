// A variant file (framework/shaders/variants/) replaces a solution file for
// one configuration; it must stay the original plus its intended change, or a
// fix made to the original silently goes missing there (it happened: the
// meshes variant of surfaceAt lost the hit points' re-projection). So every
// code line of the original must appear in the variant, except the few lines
// the variant's change rewrites, listed here with the variant.
#include "paths.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

using namespace raylab;

namespace {

// The file's code lines: trimmed, without comments, lab markers and blanks.
std::vector<std::string> codeLines(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        const std::size_t comment = line.find("//");
        if (comment != std::string::npos) line.erase(comment);
        const std::size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos) continue;
        line = line.substr(first, line.find_last_not_of(" \t") - first + 1);
        lines.push_back(line);
    }
    return lines;
}

// Code lines of ORIGINAL that VARIANT lacks (each line counted as often as
// it occurs).
std::vector<std::string> missingLines(const std::string& original, const std::string& variant) {
    std::vector<std::string> have = codeLines(variant), missing;
    for (const std::string& line : codeLines(original)) {
        auto at = std::find(have.begin(), have.end(), line);
        if (at == have.end()) missing.push_back(line);
        else have.erase(at);
    }
    return missing;
}

struct Variant {
    const char* original;
    const char* variant;
    std::vector<std::string> rewritten;  // the original's lines the change replaces
};

const Variant kVariants[] = {
    {"solution/05-primitives/surface_at.glsl",
     "framework/shaders/variants/meshes/08-full/surface_at.glsl",
     {}},
    {"solution/04-recursion/trace.glsl",
     "framework/shaders/variants/weight-cut/04-recursion/trace.glsl",
     {"if (glass.xyz != vec3(0.0) && stackSize < MAX_DEPTH) {",
      "current.weight * (1.0 - F), current.depth + 1);",
      "current.weight * reflectance, current.depth + 1);"}},
    {"solution/06-textures/glow.glsl",
     "framework/shaders/variants/old-path/06-textures/glow.glsl",
     {}},
    {"solution/08-full/light_visibility.glsl",
     "framework/shaders/variants/old-path/08-full/light_visibility.glsl",
     {"if (dot(normal, dir) <= 0.0) return false;",
      "return !findBlocker(Ray(offsetRayOrigin(point, normal), dir), distanceToLight);"}},
    {"solution/08-full/find_closest.glsl",
     "framework/shaders/variants/old-path/08-full/find_closest.glsl",
     {"vec3 invDir = inverseDirection(ray.dir);",
      "for (int g = 0; g < uTriangleGroupCount && !(stopAtFirst && hit.id >= 0); ++g) {",
      "vec3 lo = uTriangleGroupLow[g].xyz, hi = uTriangleGroupHigh[g].xyz;",
      "vec3 pad = 1e-4 * (abs(lo) + abs(hi)) + 1e-5;",
      "if (enterBox(ray.origin, invDir, lo - pad, hi + pad, hit.t) == T_FAR) continue;",
      "int first = int(uTriangleGroupLow[g].w), end = first + int(uTriangleGroupHigh[g].w);",
      "for (int i = first; i < end && !(stopAtFirst && hit.id >= 0); ++i)", "}"}},
    {"solution/08-full/test_spheres.glsl",
     "framework/shaders/variants/tree-all/08-full/test_spheres.glsl",
     {}},
    {"solution/08-full/light_visibility.glsl",
     "framework/shaders/variants/light-buffer/08-full/light_visibility.glsl",
     {"return !findBlocker(Ray(offsetRayOrigin(point, normal), dir), distanceToLight);"}},
    {"solution/08-full/test_spheres.glsl",
     "framework/shaders/variants/eye-cells/08-full/test_spheres.glsl",
     {"if (enterNode(0, ray.origin, invDir, hit.t, first, code) == T_FAR) return;",
      // A waiting node's first and code on the stack, not its index: no read at the pop.
      "stackNode[size] = nearA ? first + 1 : first;",
      // One read of the sphere: WebGL clamps every indexed read.
      "keepNearer(hit, intersectSphere(ray, uSpheres[i].xyz, uSpheres[i].w), KIND_SPHERE, i);",
      "int node = 0;", "node = stackNode[size];", "first = int(bvhNodeLow(node).w);",
      "code = int(bvhNodeHigh(node).w);"}},
    {"solution/02-shading/blinn_phong.glsl",
     "framework/shaders/variants/shared-work/02-shading/blinn_phong.glsl",
     {"for (int i = 0; i < uLightCount; ++i) {"}},
    {"solution/08-full/find_closest.glsl",
     "framework/shaders/variants/shared-work/08-full/find_closest.glsl",
     // The triangle groups one by one (testTriangleGroup), the ray's shear worked out once.
     {"for (int g = 0; g < uTriangleGroupCount && !(stopAtFirst && hit.id >= 0); ++g) {",
      "if (enterBox(ray.origin, invDir, lo - pad, hi + pad, hit.t) == T_FAR) continue;",
      "keepNearer(hit, intersectTriangle(ray, uTriangleVertices[3 * i], uTriangleVertices[3 * i + "
      "1], uTriangleVertices[3 * i + 2]),"}},
    {"solution/06-textures/glow.glsl",
     "framework/shaders/variants/shared-work/08-full/glow.glsl",
     {"Hit blocker;",
      "if (findClosest(ray, blocker) && blocker.id != objectId(KIND_SPHERE, uGlowSphere) && "
      "blocker.t < tc) return vec3(0.0);"}},
    {"solution/08-full/find_closest.glsl",
     "framework/shaders/variants/tree-all/08-full/find_closest.glsl",
     {"for (int i = 0; i < uDiscCount && !(stopAtFirst && hit.id >= 0); ++i)",
      "keepNearer(hit, intersectDisc(ray, uDiscs[i].xyz, uDiscNormals[i], uDiscs[i].w), KIND_DISC, "
      "i);",
      "vec3 invDir = inverseDirection(ray.dir);",
      "for (int g = 0; g < uTriangleGroupCount && !(stopAtFirst && hit.id >= 0); ++g) {",
      "vec3 lo = uTriangleGroupLow[g].xyz, hi = uTriangleGroupHigh[g].xyz;",
      "vec3 pad = 1e-4 * (abs(lo) + abs(hi)) + 1e-5;",
      "if (enterBox(ray.origin, invDir, lo - pad, hi + pad, hit.t) == T_FAR) continue;",
      "int first = int(uTriangleGroupLow[g].w), end = first + int(uTriangleGroupHigh[g].w);",
      "for (int i = first; i < end && !(stopAtFirst && hit.id >= 0); ++i)",
      "keepNearer(hit, intersectTriangle(ray, uTriangleVertices[3 * i], uTriangleVertices[3 * i + "
      "1], uTriangleVertices[3 * i + 2]),",
      "KIND_TRIANGLE, i);", "}"}},
};

}  // namespace

TEST(ShaderVariants, EachVariantKeepsEveryLineOfItsOriginalButItsChange) {
    for (const Variant& v : kVariants) {
        SCOPED_TRACE(v.variant);
        const std::string original = test::readFile(projectRoot() / v.original);
        const std::string variant = test::readFile(projectRoot() / v.variant);
        EXPECT_EQ(missingLines(original, variant), v.rewritten);
    }
}

// The comparison can fail: a line added to the original and not to the
// variant is reported.
TEST(ShaderVariants, ALineAddedToTheOriginalOnlyIsReported) {
    const Variant& v = kVariants[0];
    const std::string original = test::readFile(projectRoot() / v.original);
    const std::string variant = test::readFile(projectRoot() / v.variant);
    const std::string edited = original + "\nfloat addedLater() { return 1.0; }\n";
    EXPECT_EQ(missingLines(edited, variant),
              std::vector<std::string>{"float addedLater() { return 1.0; }"});
}
