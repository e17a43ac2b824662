// The rows of `raylab bench`: their Pareto front, their names, and the
// helpers the writers share (bench_rows.h).
#include "bench_rows.h"
#include "bench_report.h"

#include "atomic_file.h"
#include "error.h"
#include "paths.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace raylab {

namespace bench {

// ---------------------------------------------------------------- numbers

// Measured: a value the Pareto front and the plot can use.
bool measured(const BenchRow& r) {
    return std::isfinite(r.frameMs) && std::isfinite(r.rmse) && r.frameMs >= 0 && r.rmse >= 0;
}

// The scenes in order of first appearance, each with its rows' indices.
std::vector<std::pair<std::string, std::vector<std::size_t>>>
byScene(const std::vector<BenchRow>& rows) {
    std::vector<std::pair<std::string, std::vector<std::size_t>>> groups;
    std::map<std::string, std::size_t> where;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        auto [it, fresh] = where.emplace(rows[i].scene, groups.size());
        if (fresh) groups.push_back({rows[i].scene, {}});
        groups[it->second].second.push_back(i);
    }
    return groups;
}

// INDICES sorted by frame time (stable: equal times keep their order; rows
// without a time go last).
void sortByFrameTime(std::vector<std::size_t>& indices, const std::vector<BenchRow>& rows) {
    std::stable_sort(indices.begin(), indices.end(), [&](std::size_t a, std::size_t b) {
        const bool fa = std::isfinite(rows[a].frameMs), fb = std::isfinite(rows[b].frameMs);
        if (fa != fb) return fa;
        return fa && rows[a].frameMs < rows[b].frameMs;
    });
}

// Control characters (a newline in a scene name) would break a line-based
// format; they become spaces.
std::string oneLine(const std::string& s) {
    std::string out = s;
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    return out;
}

}  // namespace bench

using namespace bench;
namespace fs = std::filesystem;

// ---------------------------------------------------------------- Pareto

std::vector<std::size_t> paretoFront(const std::vector<BenchRow>& rows) {
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const BenchRow& a = rows[i];
        if (!measured(a)) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < rows.size() && !dominated; ++j) {
            const BenchRow& b = rows[j];
            if (j == i || b.scene != a.scene || !measured(b)) continue;
            dominated = b.frameMs <= a.frameMs && b.rmse <= a.rmse &&
                        (b.frameMs < a.frameMs || b.rmse < a.rmse);
        }
        if (!dominated) front.push_back(i);
    }
    return front;
}

std::string benchSettingName(const BenchRow& r) {
    const std::string size = " " + std::to_string(r.width) + "x" + std::to_string(r.height) + " d" +
                             std::to_string(r.depth);
    if (r.engine == "embree") return "embree-cast" + (r.lever.empty() ? "" : "+" + r.lever) + size;
    std::vector<std::string> on;
    if (!r.lever.empty()) on.push_back(r.lever);
    if (!r.bvh) on.push_back("linear");  // the BVH is the default
    if (r.specialized) on.push_back("spec");
    if (r.numerics != "robust") on.push_back(r.numerics);
    if (r.torusSolver == "closed-form") on.push_back("cf-torus");
    else if (r.torusSolver != "robust") on.push_back(r.torusSolver + "-torus");
    if (!r.shadows) on.push_back("no-shadow");
    std::string name;
    for (const std::string& s : on) name += (name.empty() ? "" : "+") + s;
    if (name.empty()) name = "baseline";
    return name + size;
}

std::string rayLever(const std::string& lever) {
    // "tree-all", "lbuf" and "eye" change how the rays find objects, not which.
    std::string kept, part;
    std::istringstream parts(lever);
    while (std::getline(parts, part, '+'))
        if (part != "tree-all" && part != "lbuf" && part != "eye")
            kept += (kept.empty() ? "" : "+") + part;
    return kept;
}

// ---------------------------------------------------------------- all three

void writeBenchFiles(const std::vector<BenchRow>& rows, const fs::path& dir,
                     const std::string& title, const std::string& commandLine, bool plot) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Error("cannot create folder " + displayPath(dir) + ": " + ec.message());
    writeTextFileAtomic(dir / "bench.csv", benchCsv(rows));
    writeTextFileAtomic(dir / "bench.md",
                        benchMarkdown(rows, title, commandLine, plot ? "bench.png" : ""));
    if (plot) writeBenchPlot(rows, dir / "bench.png", title);
}

}  // namespace raylab
