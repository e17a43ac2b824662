// The double-precision references behind the function checks agree with
// values worked out by hand, and the tables hold the hard cases they promise.
#include "function_checks.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace raylab;

namespace {

const FunctionSpec& spec(const std::string& name) {
    for (const FunctionSpec& s : functionSpecs())
        if (s.name == name) return s;
    throw std::runtime_error("no function spec " + name);
}

glm::dvec4 referenceFor(const std::string& name, const std::string& label) {
    const FunctionSpec& s = spec(name);
    auto it = std::find_if(s.cases.begin(), s.cases.end(),
                           [&](const FunctionCase& c) { return c.label == label; });
    if (it == s.cases.end()) throw std::runtime_error(name + " has no case '" + label + "'");
    return s.reference(*it);
}

}  // namespace

TEST(FunctionCases, SphereReferenceByHand) {
    EXPECT_DOUBLE_EQ(referenceFor("intersectSphere", "head-on from outside").x,
                     4.0);  // from z = -5 to the surface at -1
    EXPECT_DOUBLE_EQ(referenceFor("intersectSphere", "from the centre (inside)").x,
                     1.0);  // the exit, one radius away
    EXPECT_DOUBLE_EQ(referenceFor("intersectSphere", "sphere behind the ray").x, -1.0);  // NO_HIT
    EXPECT_DOUBLE_EQ(referenceFor("intersectSphere", "starting on the surface, entering").x,
                     2.0);  // the far side
    EXPECT_DOUBLE_EQ(referenceFor("intersectSphere", "starting on the surface, leaving").x, -1.0);
}

TEST(FunctionCases, PrimitivesReferenceByHand) {
    EXPECT_DOUBLE_EQ(referenceFor("intersectPlane", "straight down").x, 2.0);
    EXPECT_DOUBLE_EQ(referenceFor("intersectPlane", "parallel, above").x, -1.0);
    EXPECT_DOUBLE_EQ(referenceFor("intersectDisc", "inside the rim").x,
                     2.0);  // the disc lies at y = 1
    EXPECT_DOUBLE_EQ(referenceFor("intersectDisc", "diagonal, outside (1.5, 1.5)").x,
                     -1.0);  // |(1.5, 1.5)| > 2
    EXPECT_DOUBLE_EQ(referenceFor("intersectTriangle", "back face, inside (both sides count)").x,
                     3.0);
    EXPECT_DOUBLE_EQ(referenceFor("intersectTriangle", "the parallelogram's other half").x, -1.0);
}

TEST(FunctionCases, FresnelAndUvReferenceByHand) {
    EXPECT_NEAR(referenceFor("fresnelDielectric", "ior 1.5, cos 1").x, 0.04,
                1e-12);  // ((1.5 - 1) / (1.5 + 1))^2
    EXPECT_NEAR(referenceFor("fresnelDielectric", "ior 1.5, cos 0").x, 1.0,
                1e-12);  // grazing: a mirror
    glm::dvec4 gold = referenceFor("fresnelConductor", "gold, cos 1");
    EXPECT_GT(gold.x, gold.z);  // gold reflects red more than blue
    glm::dvec4 east = referenceFor("sphereUV", "-z (east of +x)");
    EXPECT_NEAR(east.x, 0.75, 1e-12);
    EXPECT_NEAR(east.y, 0.5, 1e-12);
    EXPECT_NEAR(referenceFor("sphereUV", "north pole").y, 1.0, 1e-12);
    glm::dvec4 tile = referenceFor("planeUV", "floor, one tile along x");
    EXPECT_NEAR(std::abs(tile.x) + std::abs(tile.y), 1.0, 1e-12);  // 2 units at tile size 2
}

TEST(FunctionCases, TablesHoldTheHardCases) {
    auto has = [](const std::string& name, const std::string& label) {
        const auto& cases = spec(name).cases;
        return std::any_of(cases.begin(), cases.end(),
                           [&](const FunctionCase& c) { return c.label == label; });
    };
    EXPECT_TRUE(has("intersectSphere", "tangent ray"));
    EXPECT_TRUE(has("intersectSphere", "starting on the surface, leaving"));
    EXPECT_TRUE(has("intersectPlane", "parallel, in the plane"));
    EXPECT_TRUE(has("intersectTriangle", "on the edge a-b"));
    EXPECT_TRUE(has("sphereUV", "across the seam"));
    for (const FunctionSpec& s : functionSpecs()) EXPECT_GE(s.cases.size(), 6u) << s.name;
}

TEST(FunctionCases, ComparisonRejectsAWrongAnswerAndNaN) {
    const FunctionSpec& s = spec("intersectSphere");
    const FunctionCase& head = s.cases.front();
    glm::dvec4 want = s.reference(head);
    EXPECT_EQ(s.compare(head, want, want), "");
    EXPECT_NE(s.compare(head, want + glm::dvec4(0.01, 0, 0, 0), want), "");
    EXPECT_NE(s.compare(head, glm::dvec4(-1, 0, 0, 1), want).find("got no hit"), std::string::npos);
    EXPECT_NE(s.compare(head, glm::dvec4(std::nan(""), 0, 0, 1), want).find("NaN"),
              std::string::npos);
}
