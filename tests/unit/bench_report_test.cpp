// The report half of `raylab bench`: the Pareto front per scene, the CSV and
// Markdown forms, and the gnuplot scatter plot (PNG) with its error when
// gnuplot is missing or fails.
#include "bench_report.h"
#include "error.h"
#include "image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <set>
#include <sstream>

using namespace raylab;
namespace fs = std::filesystem;
using raylab::test::readFile;
using raylab::test::ScratchDir;

namespace {

BenchRow row(const std::string& scene, double frameMs, double rmse) {
    BenchRow r;
    r.scene = scene;
    r.width = 800;
    r.height = 600;
    r.depth = 8;
    r.frameMs = frameMs;
    r.compileMs = 120.4;
    r.rmse = rmse;
    r.psnr = rmse > 0 ? -20.0 * std::log10(rmse) : INFINITY;
    r.maxErr = rmse * 10;
    r.badPxShare = rmse * 2;
    r.depthErrP99Ulp = 3;
    return r;
}

// Two scenes with several settings each, one exact (RMSE 0), like a real run.
std::vector<BenchRow> sampleRows() {
    std::vector<BenchRow> rows;
    const double lite[][2] = {
        {42.0, 0.0012}, {18.5, 0.0020}, {9.1, 0.0060}, {30.0, 0.0030}, {61.0, 0.0}};
    for (int i = 0; i < 5; ++i) {
        BenchRow r = row("lite", lite[i][0], lite[i][1]);
        r.bvh = i % 2 == 1;
        r.specialized = i >= 2;
        r.numerics = i == 3 ? "naive" : "robust";
        r.depth = i == 4 ? 4 : 8;
        rows.push_back(r);
    }
    const double pro[][2] = {{210.0, 0.0040}, {95.0, 0.0048}, {130.0, 0.0120}, {70.0, 0.0300}};
    for (int i = 0; i < 4; ++i) {
        BenchRow r = row("pro", pro[i][0], pro[i][1]);
        r.bvh = i >= 1;
        r.specialized = i == 1 || i == 3;
        r.torusSolver = i == 2 ? "closed-form" : "robust";
        r.shadows = i != 3;
        r.width = i == 3 ? 640 : 800;
        r.height = i == 3 ? 360 : 600;
        r.depth = i == 0 ? 6 : 8;  // every setting name differs from lite's
        rows.push_back(r);
    }
    return rows;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) { return e.what(); }
    return "(no error)";
}

// Sets an environment variable for one scope and puts the old value back.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (old_) ::setenv(name_, old_->c_str(), 1);
        else ::unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

const std::string kGnuplotMissing =
    "gnuplot not found: install gnuplot-nox (bash install.sh --test does)";

}  // namespace

// ---------------------------------------------------------------- Pareto

TEST(BenchPareto, DominatedRowsAreOutFasterButWorseRowsStayPerScene) {
    std::vector<BenchRow> rows = {
        row("a", 10, 0.01),   // 0: on the front
        row("a", 20, 0.02),   // 1: slower and worse than 0
        row("a", 5, 0.05),    // 2: faster but worse: kept
        row("a", 10, 0.01),   // 3: an exact tie with 0: both kept
        row("a", 10, 0.02),   // 4: as fast as 0 but worse
        row("b", 30, 0.03),   // 5: 0 would beat it, but 0 is another scene
        row("b", 40, 0.001),  // 6: slower but better than 5: kept
        row("b", 50, 0.002),  // 7: beaten by 6
        row("a", 20, 0.01),   // 8: as good as 0 but slower
    };
    EXPECT_EQ(paretoFront(rows), (std::vector<std::size_t>{0, 2, 3, 5, 6}));
}

TEST(BenchPareto, UnmeasuredRowsAreNeverOnItAndBeatNothing) {
    std::vector<BenchRow> rows = {row("a", 1, NAN), row("a", 100, 0.5), row("a", INFINITY, 0.0),
                                  row("a", NAN, 0.1)};
    EXPECT_EQ(paretoFront(rows), (std::vector<std::size_t>{1}));
    EXPECT_TRUE(paretoFront({}).empty());
}

TEST(BenchPareto, ExactRowsCountAsBest) {
    std::vector<BenchRow> rows = {row("a", 50, 0.0), row("a", 60, 0.0), row("a", 10, 0.2)};
    EXPECT_EQ(paretoFront(rows), (std::vector<std::size_t>{0, 2}));
}

// ---------------------------------------------------------------- names

TEST(BenchSettingName, NamesTheSwitchesSizeAndDepth) {
    BenchRow r = row("lite", 1, 0.1);
    EXPECT_EQ(benchSettingName(r), "linear 800x600 d8");
    r.bvh = true;
    r.specialized = true;
    EXPECT_EQ(benchSettingName(r), "spec 800x600 d8");
    r.numerics = "naive";
    r.torusSolver = "closed-form";
    r.shadows = false;
    r.depth = 3;
    EXPECT_EQ(benchSettingName(r), "spec+naive+cf-torus+no-shadow 800x600 d3");
}

// ---------------------------------------------------------------- CSV

TEST(BenchCsv, HeaderRowsAndNumbers) {
    std::vector<BenchRow> rows = sampleRows();
    const std::vector<std::string> out = lines(benchCsv(rows));
    ASSERT_EQ(out.size(), rows.size() + 1);
    EXPECT_EQ(out[0], "scene,width,height,depth,shadows,torus_solver,bvh,specialized,numerics,"
                      "frame_ms,compile_ms,rmse,psnr,max_err,"
                      "bad_px_share,depth_err_p99_ulp,engine,lever,rays,pareto\r");
    // Row 1 of the sample: lite, bvh, 18.5 ms - on the front; row 3 is not.
    EXPECT_EQ(out[2].rfind("lite,800,600,8,1,robust,1,0,robust,18.5,120.4,0.002,", 0), 0u)
        << out[2];
    EXPECT_EQ(out[2].substr(out[2].size() - 3), ",1\r");
    EXPECT_EQ(out[4].substr(out[4].size() - 3), ",0\r");
    // Every line ends CRLF and has 20 fields (none of these need quotes).
    for (const std::string& l : out) {
        EXPECT_EQ(l.back(), '\r') << l;
        EXPECT_EQ(std::count(l.begin(), l.end(), ','), 19) << l;
    }
}

TEST(BenchCsv, ExactValuesBooleansAndPareto) {
    BenchRow r = row("lite", 12.5, 0.0);
    r.compileMs = 0.1;
    r.maxErr = 0;
    r.badPxShare = 0;
    r.depthErrP99Ulp = 1.5;
    r.shadows = false;
    r.specialized = true;
    r.torusSolver = "closed-form";
    r.numerics = "naive";
    r.lever = "weight-cut";
    BenchRow slow = row("lite", 20, 0.5);
    slow.psnr = 6.02;
    slow.depthErrP99Ulp = NAN;
    // The Embree row: no picture, so no error figures, and not on the front.
    BenchRow embree = row("lite", 5, NAN);
    embree.engine = "embree";
    embree.rays = 1234;
    embree.psnr = embree.maxErr = embree.badPxShare = embree.depthErrP99Ulp = NAN;
    const std::vector<std::string> out = lines(benchCsv({r, slow, embree}));
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(out[1], "lite,800,600,8,0,closed-form,0,1,naive,12.5,0.1,0,inf,0,0,1.5,glsl,"
                      "weight-cut,0,1\r");
    // Beaten by the row above; a NaN is an empty field.
    EXPECT_EQ(out[2], "lite,800,600,8,1,robust,0,0,robust,20,120.4,0.5,6.02,5,1,,glsl,,0,0\r");
    EXPECT_EQ(out[3], "lite,800,600,8,1,robust,0,0,robust,5,120.4,,,,,,embree,,1234,0\r");
    EXPECT_EQ(benchSettingName(embree), "embree-cast 800x600 d8");
    EXPECT_EQ(benchSettingName(r), "weight-cut+linear+spec+naive+cf-torus+no-shadow 800x600 d8");
}

TEST(BenchCsv, QuotesAndDefusesSceneNames) {
    std::vector<BenchRow> rows = {row("lite, \"big\"", 10, 0.01),
                                  row("=HYPERLINK(\"x\")", 10, 0.01)};
    const std::vector<std::string> out = lines(benchCsv(rows));
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[1].rfind("\"lite, \"\"big\"\"\",800,600,8,", 0), 0u) << out[1];
    EXPECT_EQ(out[2].rfind("\"'=HYPERLINK(\"\"x\"\")\",800,", 0), 0u) << out[2];
    // Different scenes: both on their own front.
    EXPECT_EQ(out[1].substr(out[1].size() - 3), ",1\r");
    EXPECT_EQ(out[2].substr(out[2].size() - 3), ",1\r");
}

TEST(BenchCsv, EmptyIsTheHeaderOnly) { EXPECT_EQ(lines(benchCsv({})).size(), 1u); }

// ---------------------------------------------------------------- Markdown

TEST(BenchMarkdown, EveryRowGroupedByScene) {
    std::vector<BenchRow> rows = sampleRows();
    const std::string md =
        benchMarkdown(rows, "Bench on llvmpipe", "raylab bench --scenes lite,pro", "bench.png");
    EXPECT_EQ(md.rfind("# Bench on llvmpipe\n", 0), 0u);
    EXPECT_NE(md.find("`raylab bench --scenes lite,pro`"), std::string::npos);
    EXPECT_NE(md.find("![frame time against RMSE, one colour per scene](bench.png)"),
              std::string::npos);
    const std::size_t lite = md.find("\n## lite\n"), pro = md.find("\n## pro\n");
    ASSERT_NE(lite, std::string::npos);
    ASSERT_NE(pro, std::string::npos);
    EXPECT_LT(lite, pro);

    // One table line per row, under its scene's heading, readable units.
    std::size_t tableRows = 0;
    for (const std::string& l : lines(md))
        if (l.rfind("| ", 0) == 0 && l.rfind("| :", 0) != 0 &&
            l.find(" | Setting |") == std::string::npos)
            ++tableRows;
    EXPECT_EQ(tableRows, rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::size_t at = std::min(md.find("| " + benchSettingName(rows[i]) + " |"),
                                        md.find("| **" + benchSettingName(rows[i]) + "** |"));
        ASSERT_NE(at, std::string::npos) << benchSettingName(rows[i]);
        EXPECT_EQ(at > pro, rows[i].scene == "pro") << i;
    }
    EXPECT_NE(md.find("| 18.5 | n/a | 120.4 | 0.51 | 0.002 | 54.0 | 5.1 | 0.40 % | 3.0 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| 0.00 | 0 | inf |"), std::string::npos) << md;  // the exact row

    // Pareto rows are marked: lite 9.1 / 18.5 / 42.0 / 61.0 (exact), pro 70 / 95 / 210.
    std::size_t marked = 0;
    for (std::size_t p = md.find("| **yes** |"); p != std::string::npos;
         p = md.find("| **yes** |", p + 1))
        ++marked;
    EXPECT_EQ(marked, paretoFront(rows).size());
    EXPECT_EQ(marked, 7u);
    EXPECT_NE(md.find("| **yes** | **linear+spec 800x600 d8** |"), std::string::npos);
    EXPECT_NE(md.find("|  | spec+naive 800x600 d8 |"),
              std::string::npos);  // 30 ms, beaten by 18.5 ms
}

TEST(BenchMarkdown, EmbreeRowGivesEveryRowWithTheSameRaysItsRatio) {
    BenchRow glsl = row("pro", 300, 0.01);
    BenchRow half = row("pro", 30, 0.05);
    half.width = 400;
    half.height = 300;
    BenchRow embree = row("pro", 200, NAN);
    embree.engine = "embree";
    embree.rays = 1200000;
    embree.compileMs = 2.5;
    std::string md = benchMarkdown({glsl, half, embree}, "t", "c");
    EXPECT_NE(md.find("| 300.0 | 1.50 | 120.4 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| 30.0 | n/a | 120.4 |"), std::string::npos) << md;  // other rays
    EXPECT_NE(md.find("| embree-cast 800x600 d8 |"), std::string::npos) << md;
    EXPECT_NE(md.find("casting the 1200000 rays of that frame"), std::string::npos) << md;
    EXPECT_NE(md.find("BVH build: 2.5 ms"), std::string::npos) << md;
    // Not built: the row stays, its time is n/a, and the page says why.
    embree.frameMs = NAN;
    md = benchMarkdown({glsl, embree}, "t", "c");
    EXPECT_NE(md.find("| 300.0 | n/a | 120.4 |"), std::string::npos) << md;
    EXPECT_NE(md.find("Embree not built"), std::string::npos) << md;
    // A lever's rows are set against the Embree row of the lever's own rays.
    embree.frameMs = 200;
    BenchRow cut = glsl;
    cut.lever = "wcut1/255";
    cut.frameMs = 100;
    BenchRow embreeCut = embree;
    embreeCut.lever = "wcut1/255";
    embreeCut.frameMs = 50;
    md = benchMarkdown({glsl, cut, embree, embreeCut}, "t", "c");
    EXPECT_NE(md.find("wcut1/255+linear 800x600 d8** | 800x600 | 8 | yes | robust | no | no | "
                      "robust | 100.0 | 2.00 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| 300.0 | 1.50 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| embree-cast+wcut1/255 800x600 d8 |"), std::string::npos) << md;
    // tree-all finds the same rays differently: set against the lever's own
    // Embree row, not against one of its own.
    BenchRow treeAll = cut;
    treeAll.lever = "tree-all+wcut1/255";
    treeAll.frameMs = 75;
    md = benchMarkdown({treeAll, embree, embreeCut}, "t", "c");
    EXPECT_NE(md.find("| 75.0 | 1.50 |"), std::string::npos) << md;
    EXPECT_EQ(rayLever("tree-all"), "");
    EXPECT_EQ(rayLever("tree-all+wcut1/255"), "wcut1/255");
    EXPECT_EQ(rayLever("old-path"), "old-path");
    EXPECT_EQ(rayLever("wcut1/255+shared+lbuf"), "wcut1/255+shared");
    EXPECT_EQ(rayLever("wcut1/255+shared+lbuf+eye"), "wcut1/255+shared");
    // No Embree row: no Embree line.
    EXPECT_EQ(benchMarkdown({glsl}, "t", "c").find("embree-cast"), std::string::npos);
}

TEST(BenchMarkdown, EscapesTableBreakers) {
    const std::string md = benchMarkdown({row("a|b_c", 10, 0.01)}, "t", "run `x`");
    EXPECT_NE(md.find("## a\\|b\\_c\n"), std::string::npos) << md;
    EXPECT_NE(md.find("Made by `` run `x` ``\n"), std::string::npos) << md;
    EXPECT_EQ(md.find("bench.png"), std::string::npos);
}

// ---------------------------------------------------------------- plot

TEST(BenchPlot, IsAReadablePng) {
    ScratchDir dir;
    ScopedEnv tmp("TMPDIR", (dir / "").string());
    fs::create_directories(dir / "out");
    const fs::path png = dir / "out" / "bench.png";
    writeBenchPlot(sampleRows(), png, "RayLab bench test");

    const Image image = loadPng(png);
    EXPECT_EQ(image.width, 1280);
    EXPECT_EQ(image.height, 800);
    // Not one flat colour: a white background with many other colours (text,
    // grid, anti-aliased points), among them both scenes' colours.
    std::set<std::uint32_t> colours;
    std::size_t white = 0, blue = 0, red = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            colours.insert(std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2]);
            white += p[0] == 255 && p[1] == 255 && p[2] == 255;
            blue += p[0] == 0x1f && p[1] == 0x77 && p[2] == 0xb4;
            red += p[0] == 0xd6 && p[1] == 0x27 && p[2] == 0x28;
        }
    EXPECT_GT(colours.size(), 20u);
    EXPECT_GT(white, std::size_t(image.width) * image.height / 2);
    EXPECT_GT(blue, 100u);  // lite's points, step line and labels
    EXPECT_GT(red, 100u);   // pro's

    // Written atomically; gnuplot's private folder is gone.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "out"), fs::directory_iterator()), 1);
    for (const auto& e : fs::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().filename(), "out") << e.path();
}

TEST(BenchPlot, OneRowAndOnlyExactRowsStillPlot) {
    ScratchDir dir;
    writeBenchPlot({row("lite", 16.0, 0.0)}, dir / "one.png");
    const Image image = loadPng(dir / "one.png");
    EXPECT_EQ(image.width, 1280);
    EXPECT_EQ(image.height, 800);
}

TEST(BenchPlot, NothingToPlotIsAnError) {
    ScratchDir dir;
    const std::string e = errorOf([&] {
        writeBenchPlot({row("lite", NAN, 0.1), row("lite", 0, 0.1)}, dir / "x.png");
    });
    EXPECT_NE(e.find("no row has a measured frame time and RMSE"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(BenchPlot, MissingGnuplotIsNamed) {
    ScratchDir dir;
    const fs::path png = dir / "bench.png";
    EXPECT_EQ(errorOf([&] { writeBenchPlot(sampleRows(), png, "t", "raylab-no-such-gnuplot"); }),
              kGnuplotMissing);
    EXPECT_EQ(errorOf([&] { writeBenchPlot(sampleRows(), png, "t", (dir / "gnuplot").string()); }),
              kGnuplotMissing);
    {
        ScopedEnv path("PATH", "");
        EXPECT_EQ(errorOf([&] { writeBenchPlot(sampleRows(), png); }), kGnuplotMissing);
    }
    EXPECT_FALSE(fs::exists(png));
}

TEST(BenchPlot, FailingGnuplotIsAnErrorAndLeavesNoFile) {
    ScratchDir dir;
    const fs::path png = dir / "bench.png";
    const std::string e = errorOf([&] { writeBenchPlot(sampleRows(), png, "t", "false"); });
    EXPECT_NE(e.find("cannot plot"), std::string::npos) << e;
    EXPECT_NE(e.find("gnuplot exit code 1"), std::string::npos) << e;
    // `true` exits 0 but draws nothing.
    const std::string e2 = errorOf([&] { writeBenchPlot(sampleRows(), png, "t", "true"); });
    EXPECT_NE(e2.find("gnuplot wrote no PNG file"), std::string::npos) << e2;
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

// ---------------------------------------------------------------- all three

TEST(BenchFiles, WritesCsvMarkdownAndPlot) {
    ScratchDir dir;
    const fs::path out = dir / "runs" / "today";
    const std::vector<BenchRow> rows = sampleRows();
    writeBenchFiles(rows, out, "Bench", "raylab bench --out runs/today");
    EXPECT_EQ(readFile(out / "bench.csv"), benchCsv(rows));
    EXPECT_EQ(readFile(out / "bench.md"),
              benchMarkdown(rows, "Bench", "raylab bench --out runs/today", "bench.png"));
    EXPECT_EQ(loadPng(out / "bench.png").width, 1280);
    EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 3);
}
