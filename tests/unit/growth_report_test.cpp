// The report of `raylab bench --growth` (growth_report.h): the CSV, the
// growth ratio the goal is judged by, the Markdown verdict, and the plot.
#include "error.h"
#include "growth_report.h"
#include "image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace raylab;
namespace fs = std::filesystem;
using raylab::test::ScratchDir;

namespace {

GrowthRow row(const std::string& series, bool bvh, long objects, double frameMs) {
    GrowthRow r;
    r.series = series;
    r.bvh = bvh;
    r.objects = objects;
    r.width = 160;
    r.height = 120;
    r.frameMs = frameMs;
    r.buildMs = bvh ? double(objects) / 1000.0 : NAN;
    r.bvhNodes = bvh ? int(objects) : 0;
    r.bvhDepth = bvh ? 10 : 0;
    return r;
}

std::vector<GrowthRow> sample(double at100k) {
    return {row("mesh", true, 960, 30.0),     row("mesh", false, 960, 335.0),
            row("mesh", true, 9800, 40.0),    row("mesh", false, 9800, 3468.0),
            row("mesh", true, 99224, at100k), row("mesh", true, 998000, 90.0),
            row("spheres", true, 8, 12.0),    row("spheres", false, 8, 11.0)};
}

}  // namespace

TEST(GrowthReport, CsvHasAHeaderAndOneLinePerRow) {
    const std::string csv = growthCsv(sample(57.0));
    EXPECT_EQ(
        csv.rfind("series,search,objects,width,height,frame_ms,build_ms,bvh_nodes,bvh_depth\r\n",
                  0),
        0u);
    EXPECT_NE(csv.find("mesh,bvh,99224,160,120,57,99.224,99224,10\r\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("mesh,linear,960,160,120,335,,0,0\r\n"), std::string::npos)
        << "no build time for the linear search: an empty field";
}

TEST(GrowthReport, GrowthIsBetweenTheRowsNearestTheEnds) {
    const Growth g = growthBetween(sample(57.0), "mesh", true, 1000, 100000);
    EXPECT_EQ(g.from, 960);
    EXPECT_EQ(g.to, 99224);
    EXPECT_DOUBLE_EQ(g.ratio, 57.0 / 30.0);
    const Growth none = growthBetween(sample(57.0), "mesh", false, 1000, 100000);
    EXPECT_TRUE(std::isnan(none.ratio)) << "no linear row within a factor of 2 of 100000";
    const Growth tenK = growthBetween(sample(57.0), "mesh", false, 1000, 10000);
    EXPECT_EQ(tenK.to, 9800);
    EXPECT_DOUBLE_EQ(tenK.ratio, 3468.0 / 335.0);
}

TEST(GrowthReport, MarkdownSaysWhetherTheGoalIsMet) {
    const std::string met = growthMarkdown(sample(57.0), "t", "raylab bench --growth", "n");
    EXPECT_NE(met.find("goal: at most 3x (a logarithmic walk): met"), std::string::npos) << met;
    EXPECT_NE(met.find("| 960 | 30 | 335 | 11.2x |"), std::string::npos) << met;
    const std::string missed = growthMarkdown(sample(100.0), "t", "", "");
    EXPECT_NE(missed.find("3.33x (960 -> 99224)"), std::string::npos) << missed;
    EXPECT_NE(missed.find(": missed"), std::string::npos) << missed;
}

TEST(GrowthReport, PlotIsAPngAndNothingToPlotIsAnError) {
    ScratchDir dir;
    writeGrowthPlot(sample(57.0), dir / "growth.png", "growth test");
    const Image image = loadPng(dir / "growth.png");
    EXPECT_EQ(image.width, 1280);
    EXPECT_THROW(writeGrowthPlot({}, dir / "none.png", "empty"), Error);
    EXPECT_FALSE(fs::exists(dir / "none.png"));
}
