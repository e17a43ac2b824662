// The double-precision references behind the function checks agree with
// values worked out by hand, and the tables hold the hard cases they promise.
#include "check_report.h"
#include "function_harness.h"
#include "reference_shading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

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

// The case whose label begins with PREFIX (the tables that need a scene add
// their inputs to the label).
const FunctionCase& caseStartingWith(const std::string& name, const std::string& prefix) {
    const FunctionSpec& s = spec(name);
    auto it = std::find_if(s.cases.begin(), s.cases.end(), [&](const FunctionCase& c) {
        return c.label.compare(0, prefix.size(), prefix) == 0;
    });
    if (it == s.cases.end()) throw std::runtime_error(name + " has no case '" + prefix + "...'");
    return *it;
}

glm::dvec4 referenceStartingWith(const std::string& name, const std::string& prefix) {
    return spec(name).reference(caseStartingWith(name, prefix));
}

void expectNear(const glm::dvec4& got, const glm::dvec3& want) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-9) << "component " << i;
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

TEST(FunctionCases, ShadingReferencesByHand) {
    // Ambient (0.1, 0.05, 0.02) plus light (1, 0.8, 0.6) times diffuse
    // (0.5, 0.6, 0.7) and specular (0.9, 0.8, 0.7), both at full strength.
    expectNear(referenceStartingWith("blinnPhong", "light and eye straight above"),
               {1.5, 1.17, 0.86});
    // A light behind the surface adds nothing, not even a highlight.
    expectNear(referenceStartingWith("blinnPhong", "light behind the surface, the half vector"),
               {0.1, 0.05, 0.02});
    EXPECT_EQ(referenceStartingWith("lightVisible", "light above the point").x, 1.0);
    EXPECT_EQ(referenceStartingWith("lightVisible", "a sphere between").x, 0.0);
    EXPECT_EQ(referenceStartingWith("lightVisible", "a sphere beyond the light").x, 1.0);
    EXPECT_EQ(referenceStartingWith("lightVisible", "light on the far side").x, 0.0);
    EXPECT_EQ(referenceStartingWith("lightVisible", "eye inside a sphere").x, 1.0);
    expectNear(referenceStartingWith("applyNormalMap", "flat texel"), {0, 0, 1});
    // N = y, tangent (0.8, 0.6, 0) -> T = x, B = N x T = -z; texel (0.8, 0.3,
    // 0.9) decodes to (0.6, -0.4, 0.8): (0.6, 0.8, 0.4) / |(0.6, 0.8, 0.4)|.
    expectNear(referenceStartingWith("applyNormalMap", "tangent not perpendicular"),
               glm::dvec3(0.6, 0.8, 0.4) / std::sqrt(1.16));
    expectNear(referenceStartingWith("applyColorMode", "mode 1 (BRB), colour (0.1, 0.5, 0.9)"),
               {0.9, 0.1, 0.9});
    expectNear(referenceStartingWith("applyColorMode", "mode 4 (GGR), colour (0.1, 0.5, 0.9)"),
               {0.5, 0.5, 0.1});
}

// The open level's whole functions. trace() in its stand-in world
// (trace_function_cases.cpp): the hit's
// stand-in shading is ambient (a tenth of the diffuse colour) plus the
// diffuse colour times 0.25 + 0.75 N.V, plus a tenth of the specular colour
// times 0.5 + 0.5 N.y; the sky is (0.35, 0.5, 0.75) + 0.25 dir.
TEST(FunctionCases, WholeFunctionReferencesByHand) {
    const glm::dvec3 gold(0.05, 0.04, 0.02);
    // Straight at the gold ball, depth 1: N.V = 1, N.y = 0, no specular colour.
    const std::string straight =
        "a gold ball beside a red one, ray from (0, 0, 0) along (0, 0, -1)";
    expectNear(referenceStartingWith("trace", straight + ", uMaxDepth 1"), 1.1 * gold);
    // Depth 8: the reflected ray goes straight back to the sky, (0.35, 0.5, 1),
    // weighted by the conductor's reflectance at normal incidence.
    const glm::dvec3 f0 =
        reference::fresnelConductor(1.0, {0.143, 0.374, 1.442}, {3.983, 2.385, 1.603});
    expectNear(referenceStartingWith("trace", straight + ", uMaxDepth 8"),
               1.1 * gold + f0 * glm::dvec3(0.35, 0.5, 1.0));
    // The glow: full colour straight at the sun, nothing with the sun
    // behind the eye or hidden by a plane in front of it.
    expectNear(referenceFor("sunGlow", "straight at the sun: full glow"), {1.0, 0.8, 0.5});
    expectNear(referenceFor("sunGlow", "the sun behind the eye"), {0, 0, 0});
    expectNear(referenceFor("sunGlow", "a plane in front of the sun's closest point"), {0, 0, 0});
    EXPECT_GT(referenceFor("sunGlow", "a plane behind the sun's closest point").x, 0.1);
    // The BVH walk's world of eight spheres in a row: the ray along x at
    // y = 0.1, z = -0.7 passes sphere 0 (radius 0.6, 0.71 off its centre)
    // and enters sphere 1 (centre (-7.5, 0.3 sin 1, -0.2), radius 0.7).
    const glm::dvec4 row = referenceStartingWith(
        "walkBvh", "eight spheres in a row along x, ray from (-20, 0.1, -0.7) along (1, 0, 0)");
    const double dy = 0.1 - 0.3 * std::sin(1.0), dz = -0.5;
    EXPECT_EQ(row.z, 1.0);
    EXPECT_NEAR(row.y, 12.5 - std::sqrt(0.49 - dy * dy - dz * dz), 1e-6);
    // 08's lightVisible: no shadow ray to a light behind the surface; every
    // light visible with shadows off.
    EXPECT_EQ(referenceStartingWith("lightVisibleFast", "a light behind the surface").x, 0.0);
    EXPECT_EQ(referenceStartingWith("lightVisibleFast", "shadows off").x, 1.0);
}

// The switches the checked code reads (keys N and 1, the colour mode) are
// set for each case.
TEST(FunctionCases, KeyUniformsAreSetPerCase) {
    const std::pair<const char*, const char*> switches[] = {{"applyColorMode", "uColorMode"},
                                                            {"applyNormalMap", "uNormalMaps"},
                                                            {"lightVisible", "uShadows"}};
    for (const auto& [function, uniform] : switches)
        for (const FunctionCase& c : spec(function).cases) {
            ASSERT_EQ(c.uniforms.size(), 1u) << c.label;
            EXPECT_EQ(c.uniforms.front().first, uniform) << c.label;
            if (std::string(uniform) != "uColorMode") { EXPECT_EQ(c.uniforms.front().second, 1); }
        }
    EXPECT_EQ(caseStartingWith("applyColorMode", "mode 3").uniforms.front().second, 3);
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
    // A pole with |d.y| a float step above 1: asin() needs the clamp.
    const FunctionCase& pole = caseStartingWith("sphereUV", "north pole, d.y a float step");
    EXPECT_GT(pole.in[0].y, 1.0);
    EXPECT_EQ(float(pole.in[0].y), std::nextafter(1.0f, 2.0f));  // what the harness reads
    EXPECT_LT(caseStartingWith("sphereUV", "south pole, d.y a float step").in[0].y, -1.0);
    // The tangent of a normal-map case need be neither unit nor perpendicular.
    const FunctionCase& skew = caseStartingWith("applyNormalMap", "tangent neither unit");
    EXPECT_GT(std::abs(glm::length(glm::dvec3(skew.in[1])) - 1.0), 0.1);
    EXPECT_GT(std::abs(glm::dot(glm::dvec3(skew.in[0]), glm::dvec3(skew.in[1]))), 0.1);
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

// u is compared modulo 1 (the picture repeats: u and u + 1 are the same
// place), and a failure shows the value as the function returned it.
TEST(FunctionCases, UvComparisonIsModuloOneAndShowsTheValueReturned) {
    const FunctionSpec& s = spec("sphereUV");
    const FunctionCase& c = s.cases.front();
    EXPECT_EQ(s.compare(c, glm::dvec4(1.25, 0.5, 0, 1), glm::dvec4(0.25, 0.5, 0, 1)), "");
    EXPECT_EQ(s.compare(c, glm::dvec4(0.0, 0.5, 0, 1), glm::dvec4(1.0, 0.5, 0, 1)), "");
    const std::string why = s.compare(c, glm::dvec4(0.25, 0.5, 0, 1), glm::dvec4(0.9, 0.5, 0, 1));
    EXPECT_NE(why.find("got (0.25, 0.5)"), std::string::npos) << why;
    EXPECT_NE(why.find("expected (0.9, 0.5)"), std::string::npos) << why;
    EXPECT_NE(why.find("modulo 1"), std::string::npos) << why;
    // A wrong v: no word about u.
    const std::string v = s.compare(c, glm::dvec4(0.5, 0.2, 0, 1), glm::dvec4(0.5, 0.5, 0, 1));
    EXPECT_NE(v.find("got (0.5, 0.2)"), std::string::npos) << v;
    EXPECT_EQ(v.find("modulo"), std::string::npos) << v;
    // At a pole any u is right; NaN is named.
    const FunctionCase& pole = caseStartingWith("sphereUV", "north pole, d.y a float step");
    EXPECT_EQ(s.compare(pole, glm::dvec4(0.123, 1.0, 0, 1), s.reference(pole)), "");
    EXPECT_NE(s.compare(pole, glm::dvec4(0.5, std::nan(""), 0, 1), s.reference(pole)).find("NaN"),
              std::string::npos);
}

TEST(FunctionCases, ShadingComparisonsNameTheInputAndBothAnswers) {
    const FunctionSpec& light = spec("lightVisible");
    const FunctionCase& between = caseStartingWith("lightVisible", "a sphere between");
    const std::string why =
        light.compare(between, glm::dvec4(1, 0, 0, 1), light.reference(between));
    EXPECT_NE(why.find("expected the light blocked, got visible"), std::string::npos) << why;
    EXPECT_NE(why.find("[point (0, 1, 0)"), std::string::npos) << why;
    const FunctionSpec& blinn = spec("blinnPhong");
    const FunctionCase& behind = caseStartingWith("blinnPhong", "light behind the surface, the");
    const std::string b =
        blinn.compare(behind, glm::dvec4(0.7, 0.5, 0.3, 1), blinn.reference(behind));
    EXPECT_NE(b.find("expected (0.1, 0.05, 0.02), got (0.7, 0.5, 0.3)"), std::string::npos) << b;
    EXPECT_NE(b.find("shininess 4"), std::string::npos) << b;
}

// A failing check whose harness runs the file of a function that failed
// above says so; a file the two share as their own does not count.
TEST(FunctionCases, AFailingCheckNamesTheFailedFileItRuns) {
    const std::string findClosest =
        formatReadsFailedNote(spec("findClosest"), {&spec("intersectSphere")});
    EXPECT_NE(findClosest.find("runs your intersect_sphere.glsl, where intersectSphere failed"),
              std::string::npos)
        << findClosest;
    // trace's stand-ins include fresnel.glsl (refractGlass, the Fresnel terms).
    EXPECT_NE(formatReadsFailedNote(spec("trace"), {&spec("refractGlass")}).find("fresnel.glsl"),
              std::string::npos);
    // fresnelConductor lives beside fresnelDielectric: no note.
    EXPECT_EQ(formatReadsFailedNote(spec("fresnelConductor"), {&spec("fresnelDielectric")}), "");
    // intersectSphere does not run find_closest.glsl; nothing failed above.
    EXPECT_EQ(formatReadsFailedNote(spec("intersectSphere"), {&spec("findClosest")}), "");
    EXPECT_EQ(formatReadsFailedNote(spec("findClosest"), {}), "");
}
