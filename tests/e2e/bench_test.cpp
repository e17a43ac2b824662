// `raylab bench --quick`: the smoke run CI makes of the speed-vs-error
// benchmark. No timing is asserted (machines are shared and noisy); what is
// asserted is that every setting was measured and that the error figures
// mean something: the variants that must not change the picture (BVH,
// specialised shader) have the default's error, and a cheaper setting that
// does change it (depth 2) has more.
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>

using namespace raylab::test;

namespace {

std::vector<std::map<std::string, std::string>> readCsv(const fs::path& file) {
    std::istringstream in(readFile(file));
    std::string line;
    std::vector<std::string> header;
    std::vector<std::map<std::string, std::string>> rows;
    auto split = [](std::string l) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        std::vector<std::string> f;
        std::stringstream ss(l);
        for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
        return f;
    };
    std::getline(in, line);
    header = split(line);
    while (std::getline(in, line)) {
        std::vector<std::string> f = split(line);
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < f.size(); ++i) row[header[i]] = f[i];
        rows.push_back(row);
    }
    return rows;
}

double num(const std::map<std::string, std::string>& row, const std::string& key) {
    return std::stod(row.at(key));
}

}  // namespace

TEST(Bench, QuickRunWritesTableCsvAndPlotWithMeaningfulErrors) {
    ScratchDir dir;
    CommandResult r = runRaylab("bench --quick --out " + quote((dir / "out").string()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    ASSERT_TRUE(fs::exists(dir / "out/bench.md")) << r.all();
    ASSERT_TRUE(fs::exists(dir / "out/bench.png"));
    auto rows = readCsv(dir / "out/bench.csv");
    ASSERT_EQ(rows.size(), 5u) << readFile(dir / "out/bench.csv");
    // The Embree row: the frame's rays (160x120 primary rays and more), cast
    // when this build has Embree; no picture, so no error figures.
    const auto embree = std::find_if(rows.begin(), rows.end(),
                                     [](const auto& row) { return row.at("engine") == "embree"; });
    ASSERT_NE(embree, rows.end()) << readFile(dir / "out/bench.csv");
    EXPECT_GT(num(*embree, "rays"), 160.0 * 120.0);
    EXPECT_EQ(embree->at("rmse"), "");
    const std::string md = readFile(dir / "out/bench.md");
    if (r.out.find("Embree not built") == std::string::npos) {
        EXPECT_GT(num(*embree, "frame_ms"), 0.0);
        const std::size_t at = r.out.find("agrees with the reference on ");
        ASSERT_NE(at, std::string::npos) << r.out;
        EXPECT_GE(std::stod(r.out.substr(at + 29)), 99.99) << r.out;
        EXPECT_NE(md.find("| x Embree |"), std::string::npos);
    } else {
        EXPECT_NE(md.find("Embree not built"), std::string::npos) << md;
    }
    rows.erase(embree);
    const auto *base = &rows[0], *linear = &rows[0], *spec = &rows[0], *shallow = &rows[0];
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("scene"), "lite");
        EXPECT_EQ(row.at("engine"), "glsl");
        EXPECT_GT(num(row, "frame_ms"), 0.0);
        EXPECT_GT(num(row, "compile_ms"), 0.0);
        if (row.at("bvh") == "0") linear = &row;
        else if (row.at("specialized") == "1") spec = &row;
        else if (row.at("depth") == "2") shallow = &row;
        else base = &row;
    }
    std::printf("[ figure ] rmse: default %s, linear %s, specialised %s, depth 2 %s\n",
                base->at("rmse").c_str(), linear->at("rmse").c_str(), spec->at("rmse").c_str(),
                shallow->at("rmse").c_str());
    // The GPU default is close to the double reference ...
    EXPECT_LT(num(*base, "rmse"), 0.02) << "the default frame is far from the reference";
    // ... the BVH and the specialised shader draw the same picture ...
    EXPECT_NEAR(num(*linear, "rmse"), num(*base, "rmse"), 0.002);
    EXPECT_NEAR(num(*spec, "rmse"), num(*base, "rmse"), 0.002);
    // ... and depth 2 loses the reflections the reference has.
    EXPECT_GT(num(*shallow, "rmse"), 1.5 * num(*base, "rmse"));
    EXPECT_NE(readFile(dir / "out/bench.md").find("raylab bench --quick"), std::string::npos)
        << "the table names its command";
}

TEST(Bench, BadInputFailsBeforeMeasuringAndWritesNothing) {
    ScratchDir dir;
    CommandResult r =
        runRaylab("bench --quick --scenes nosuch.json --out " + quote((dir / "out").string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("nosuch.json"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
    r = runRaylab("bench --quick --size 0x0 --out " + quote((dir / "out").string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_FALSE(fs::exists(dir / "out"));
    writeFile(dir / "file", "in the way");
    r = runRaylab("bench --quick --out " + quote((dir / "file/out").string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("cannot make this folder"), std::string::npos) << r.err;
}

TEST(Bench, FurQuickRunWritesCsvTablePlotAndTheTechniquesLimits) {
    ScratchDir dir;
    CommandResult r = runRaylab("bench --track fur --quick --out " + quote((dir / "out").string()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    auto rows = readCsv(dir / "out/fur.csv");
    ASSERT_EQ(rows.size(), 4u) << readFile(dir / "out/fur.csv");
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("mesh"), "sphere");
        EXPECT_GT(num(row, "triangles"), 100.0);
        EXPECT_GT(num(row, "frame_ms"), 0.0);
        EXPECT_GT(num(row, "buffer_bytes"), 0.0);
        EXPECT_GT(num(row, "rss_bytes"), 1e6);
        if (row.at("technique") == "shells_and_fins") {
            // 16 shells against 64: close, but not the same picture.
            EXPECT_GT(num(row, "rmse"), 0.0);
            EXPECT_LT(num(row, "rmse"), 0.1);
        } else {
            EXPECT_EQ(row.at("technique"), "fur_shader");
            EXPECT_EQ(row.at("rmse"), "") << "strands are no approximation of the shells";
        }
    }
    const std::string md = readFile(dir / "out/fur.md");
    EXPECT_NE(md.find("raylab bench --track fur --quick"), std::string::npos);
    EXPECT_NE(md.find("GL_MAX_GEOMETRY_OUTPUT_VERTICES"), std::string::npos);
    EXPECT_NE(md.find("fur shader / shells+fins"), std::string::npos);
    EXPECT_EQ(readFile(dir / "out/fur.png").substr(0, 4), "\x89PNG");
    r = runRaylab("bench --track fur --quick --scenes lite --out " +
                  quote((dir / "other").string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_FALSE(fs::exists(dir / "other"));
}

// A machine without gnuplot (a lent GPU machine): the bench says so before
// measuring, writing nothing, and names --no-plot; with it the tables come
// without a plot, and the Markdown shows none.
TEST(Bench, WithoutGnuplotItStopsFirstOrWritesTheTablesWithoutAPlot) {
    ScratchDir dir;
    const std::string noGnuplot = "env PATH=" + quote((dir / "empty").string()) + " " +
                                  quote(raylabExe().string()) + " bench --quick ";
    for (const char* track : {"raytrace", "fur"}) {
        SCOPED_TRACE(track);
        const fs::path out = dir / (std::string("plotless-") + track);
        CommandResult r =
            runCommand(noGnuplot + "--track " + track + " --out " + quote(out.string()));
        EXPECT_EQ(r.exitCode, 2) << r.all();
        EXPECT_NE(r.err.find("gnuplot not found"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("--no-plot"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
    const fs::path out = dir / "fur";
    CommandResult r = runCommand(noGnuplot + "--track fur --no-plot --out " + quote(out.string()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("no plot"), std::string::npos) << r.out;
    EXPECT_EQ(readCsv(out / "fur.csv").size(), 4u);
    EXPECT_FALSE(fs::exists(out / "fur.png"));
    EXPECT_EQ(readFile(out / "fur.md").find("fur.png"), std::string::npos);
}

// `bench --growth --quick`: the files and their rows (no speed is asserted:
// timings belong in the report, not in a test).
TEST(Bench, GrowthQuickRunWritesCsvTableAndPlot) {
    ScratchDir dir;
    CommandResult r = runRaylab("bench --growth --quick --out " + quote((dir / "out").string()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    for (const char* f : {"growth.csv", "growth.md", "growth.png"})
        EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
    const auto rows = readCsv(dir / "out" / "growth.csv");
    int meshBvh = 0, meshLinear = 0, spheres = 0;
    for (const auto& row : rows) {
        EXPECT_GT(num(row, "frame_ms"), 0.0);
        if (row.at("series") == "mesh") (row.at("search") == "bvh" ? meshBvh : meshLinear)++;
        if (row.at("series") == "spheres") ++spheres;
        if (row.at("search") == "bvh") {
            EXPECT_GE(num(row, "build_ms"), 0.0);
            EXPECT_GT(num(row, "bvh_nodes"), 0.0);
        } else {
            EXPECT_EQ(row.at("build_ms"), "") << "the linear search builds nothing";
        }
    }
    EXPECT_EQ(meshBvh, 3);
    EXPECT_EQ(meshLinear, 3);
    EXPECT_EQ(spheres, 4);
    const std::string md = readFile(dir / "out" / "growth.md");
    EXPECT_NE(md.find("## Growth of the frame time, mesh, about 1k to 100k triangles"),
              std::string::npos);
    EXPECT_NE(md.find("| 960 |"), std::string::npos) << md;
}

TEST(Bench, GrowthRefusesOptionsItCannotHonourAndWritesNothing) {
    ScratchDir dir;
    CommandResult r =
        runRaylab("bench --growth --track fur --quick --out " + quote((dir / "out").string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("--growth measures the ray tracer"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
    r = runRaylab("bench --growth --scenes lite --out " + quote((dir / "out").string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("--growth makes its own scenes"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
}
