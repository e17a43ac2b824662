// `raylab trace` prints the reference tracer's path and then the one the
// stage's own shader takes (raytrace/gpu_trace.h): through the solution the
// two agree ray by ray (object and t), through the lab as handed out they
// part; a compile error in the student's file is named at its line.
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>

using namespace raylab::test;

namespace {

struct Ray {
    std::string hit;  // "sphere 1", or "misses"
    double t = NAN;
};

// The rays of OUTPUT's part: the reference's lines "ray N (depth ...", or
// the shader's "ray N (trace, ...".
std::vector<Ray> raysOf(const std::string& output, const std::regex& line) {
    static const std::regex hit(R"(hits ([a-z ]+ \d+)(?: '[^']*')? at t=([0-9.e+-]+))");
    std::vector<Ray> out;
    std::istringstream in(output);
    for (std::string l; std::getline(in, l);) {
        if (!std::regex_search(l, line)) continue;
        std::smatch m;
        out.push_back(std::regex_search(l, m, hit) ? Ray{m[1].str(), std::stod(m[2].str())}
                                                   : Ray{"misses", NAN});
    }
    return out;
}

bool samePath(const std::vector<Ray>& a, const std::vector<Ray>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].hit != b[i].hit ||
            (!std::isnan(a[i].t) && std::abs(a[i].t - b[i].t) > 1e-3 * std::max(1.0, a[i].t)))
            return false;
    return true;
}

const std::regex kReference(R"(^ray \d+ \(depth)");
const std::regex kShader(R"(^ray \d+ \(trace,)");

}  // namespace

TEST(GpuTrace, TheSolutionsPathIsTheReferences) {
    const CommandResult r = runRaylab("trace --stage 04 --solution --pixel 400,250");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const std::vector<Ray> reference = raysOf(r.out, kReference), mine = raysOf(r.out, kShader);
    EXPECT_GE(reference.size(), 10u) << r.out;
    EXPECT_TRUE(samePath(reference, mine)) << r.out;
    EXPECT_NE(r.out.find("your shader's path (solution)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("(lightVisible, solution/03-shadows/light_visibility.glsl:"),
              std::string::npos);
}

TEST(GpuTrace, TheLabsPathPartsFromTheReferences) {
    const CommandResult r = runRaylab("trace --stage 04 --pixel 400,250");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    const std::vector<Ray> reference = raysOf(r.out, kReference), mine = raysOf(r.out, kShader);
    EXPECT_FALSE(mine.empty()) << r.out;
    EXPECT_FALSE(samePath(reference, mine)) << r.out;  // glass drawn as a mirror: no refraction
}

TEST(GpuTrace, ACompileErrorIsNamedAtItsLine) {
    ScratchDir lab;
    writeSolvedLabs(lab.path());
    replaceInFile(lab / "04-recursion" / "trace.glsl", "int stackSize = 0;", "int stackSize = ;");
    const CommandResult r =
        runRaylab("trace --stage 04 --pixel 400,250 --lab " + quote(lab.path().string()));
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_TRUE(
        std::regex_search(r.out, std::regex(R"(not traced: .*04-recursion/trace\.glsl:\d+)")))
        << r.out;
}
