// Where the grading threshold comes from: how much the SOLUTION differs from
// itself when only the renderer changes. Every check view of every stage is
// rendered with EGL and compared with the same view rendered by OSMesa (its
// own process, its own Mesa build of the shaders): the spread is printed and
// must be zero. The threshold (0.5% of pixels off by more than 8/255 after
// the 3x3 neighbourhood search) sits far above this spread and below the
// smallest signal of a caught mistake (tests/README.md). Grading always
// renders submission and solution at one size on one machine: across sizes
// the solution differs from itself by several percent of pixels (aliasing of
// textures, stars and sharp refractions at 160x120 against 320x240 scaled
// down), so sizes are never mixed.
#include "test_support.h"

#include <gtest/gtest.h>

#include <regex>

using namespace raylab::test;

TEST(GradeSpread, SolutionIsIdenticalUnderEglAndOsMesaInEveryView) {
    int views = 0;
    for (const char* stage : {"01", "02", "03", "04", "05", "06", "07", "08"}) {
        SCOPED_TRACE(stage);
        ScratchDir egl;
        CommandResult saved = runRaylab(std::string("check --stage ") + stage + " --solution --backend egl --save " + quote(egl.path()));
        ASSERT_EQ(saved.exitCode, 0) << saved.all();
        CommandResult r = runRaylab(std::string("check --stage ") + stage + " --solution --backend osmesa --against " + quote(egl.path()));
        EXPECT_EQ(r.exitCode, 0) << r.all();
        std::regex line(R"(PASS (\S+)\s+([0-9.]+)% of pixels differ \(max ([0-9]+)/255\))");
        for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), line); it != std::sregex_iterator(); ++it) {
            ++views;
            EXPECT_EQ((*it)[3].str(), "0") << "view " << (*it)[1] << " differs between EGL and OSMesa";
        }
    }
    std::printf("[ figure   ] solution EGL vs OSMesa: %d views, every pixel identical (spread 0)\n", views);
    EXPECT_GE(views, 50);
}
