// growth.csv, growth.md and growth.png (growth_report.h).
#include "growth_report.h"

#include "atomic_file.h"
#include "csv_text.h"
#include "error.h"
#include "gnuplot.h"
#include "measured_cells.h"
#include "paths.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace raylab {

using namespace bench;
namespace fs = std::filesystem;

namespace {

const GrowthRow* findGrowthRow(const std::vector<GrowthRow>& rows, const std::string& series,
                               bool bvh, long objects) {
    for (const GrowthRow& r : rows)
        if (r.series == series && r.bvh == bvh && r.objects == objects) return &r;
    return nullptr;
}

std::vector<std::string> growthSeries(const std::vector<GrowthRow>& rows) {
    std::vector<std::string> names;
    for (const GrowthRow& r : rows)
        if (std::find(names.begin(), names.end(), r.series) == names.end())
            names.push_back(r.series);
    return names;
}

std::set<long> objectsOf(const std::vector<GrowthRow>& rows, const std::string& series) {
    std::set<long> n;
    for (const GrowthRow& r : rows)
        if (r.series == series) n.insert(r.objects);
    return n;
}

std::string growthText(const Growth& g) {
    return std::isfinite(g.ratio) ? significant(g.ratio, 3) + "x (" + std::to_string(g.from) +
                                        " -> " + std::to_string(g.to) + ")"
                                  : std::string("not measured");
}

}  // namespace

std::string growthSeriesName(const GrowthRow& r) {
    return r.series + (r.bvh ? ", BVH" : ", linear");
}

std::string growthCsv(const std::vector<GrowthRow>& rows) {
    const std::string eol = "\r\n";
    std::string out =
        "series,search,objects,width,height,frame_ms,build_ms,bvh_nodes,bvh_depth" + eol;
    for (const GrowthRow& r : rows)
        out += csvText(r.series) + "," + (r.bvh ? "bvh" : "linear") + "," +
               std::to_string(r.objects) + "," + std::to_string(r.width) + "," +
               std::to_string(r.height) + "," + measuredCsv(r.frameMs) + "," +
               measuredCsv(r.buildMs) + "," + std::to_string(r.bvhNodes) + "," +
               std::to_string(r.bvhDepth) + eol;
    return out;
}

Growth growthBetween(const std::vector<GrowthRow>& rows, const std::string& series, bool bvh,
                     long from, long to) {
    auto nearest = [&](long wanted) {
        const GrowthRow* best = nullptr;
        double bestOff = std::log(2.0) + 1e-9;  // within a factor of 2
        for (const GrowthRow& r : rows) {
            if (r.series != series || r.bvh != bvh || !(r.frameMs > 0) || r.objects <= 0) continue;
            const double off = std::fabs(std::log(double(r.objects) / double(wanted)));
            if (off < bestOff) {
                bestOff = off;
                best = &r;
            }
        }
        return best;
    };
    const GrowthRow* lo = nearest(from);
    const GrowthRow* hi = nearest(to);
    Growth g;
    if (!lo || !hi || hi->objects <= lo->objects) return g;
    g.from = lo->objects;
    g.to = hi->objects;
    g.ratio = hi->frameMs / lo->frameMs;
    return g;
}

std::string growthMarkdown(const std::vector<GrowthRow>& rows, const std::string& title,
                           const std::string& commandLine, const std::string& notes,
                           const std::string& plotFile) {
    std::string md = "# " + title + "\n\n";
    if (!commandLine.empty()) md += "Made by `" + commandLine + "`.\n\n";
    if (!notes.empty()) md += notes + "\n\n";
    if (!plotFile.empty()) md += "![frame and build time against objects](" + plotFile + ")\n\n";

    const Growth bvh = growthBetween(rows, "mesh", true, 1000, 100000);
    md += "## Growth of the frame time, mesh, about 1k to 100k triangles\n\n";
    md += "- BVH: " + growthText(bvh) + "; goal: at most 3x (a logarithmic walk): " +
          (std::isfinite(bvh.ratio) ? (bvh.ratio <= 3.0 ? "met" : "missed") : "not measured") +
          "\n";
    md += "- linear search: " + growthText(growthBetween(rows, "mesh", false, 1000, 100000)) +
          "; for contrast, about 1k to 10k: " +
          growthText(growthBetween(rows, "mesh", false, 1000, 10000)) +
          " (BVH: " + growthText(growthBetween(rows, "mesh", true, 1000, 10000)) + ")\n\n";

    for (const std::string& series : growthSeries(rows)) {
        md += "## " + series + ": frame time (ms, median) by object count\n\n";
        md += "| " + std::string(series == "mesh" ? "triangles" : "spheres") +
              " | BVH | linear | linear / BVH | BVH build (ms) | nodes | depth |\n"
              "| ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
        for (long n : objectsOf(rows, series)) {
            const GrowthRow* b = findGrowthRow(rows, series, true, n);
            const GrowthRow* l = findGrowthRow(rows, series, false, n);
            md += "| " + std::to_string(n) + " | " + (b ? measuredMs(b->frameMs) : "-") + " | " +
                  (l ? measuredMs(l->frameMs) : "-") + " | " +
                  (b && l ? significant(l->frameMs / b->frameMs, 3) + "x" : std::string("-")) +
                  " | " + (b ? measuredMs(b->buildMs) : "-") + " | " +
                  (b ? std::to_string(b->bvhNodes) : "-") + " | " +
                  (b ? std::to_string(b->bvhDepth) : "-") + " |\n";
        }
        md += "\n";
    }
    return md;
}

void writeGrowthPlot(const std::vector<GrowthRow>& rows, const fs::path& pngPath,
                     const std::string& title, const std::string& gnuplot) {
    const std::string what = "cannot plot " + displayPath(pngPath) + ": ";
    double minMs = INFINITY, maxMs = 0;
    long minN = 0, maxN = 0;
    auto see = [&](double v, long n) {
        if (!(v > 0) || !std::isfinite(v) || n <= 0) return;
        minMs = std::min(minMs, v);
        maxMs = std::max(maxMs, v);
        minN = minN ? std::min(minN, n) : n;
        maxN = std::max(maxN, n);
    };
    for (const GrowthRow& r : rows) {
        see(r.frameMs, r.objects);
        if (r.bvh) see(r.buildMs, r.objects);
    }
    if (maxMs == 0) throw Error(what + "no row has a measured frame time");
    static const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e"};
    TempDir tmp;
    std::string plot;
    int k = 0;
    auto line = [&](const std::string& name, const std::string& data, const char* colour,
                    bool dashed) {
        if (data.empty()) return;
        const fs::path file = tmp.path() / ("series" + std::to_string(k++) + ".dat");
        writeBytes(file, data);
        plot += (plot.empty() ? "plot " : ", \\\n     ") + gpString(file.string()) +
                " using 1:2 with linespoints pt 7 ps 1.3 lw 2 " + (dashed ? "dt 2 " : "") +
                "lc rgb '" + colour + "' title " + gpString(name);
    };
    int s = 0;
    for (const std::string& series : growthSeries(rows)) {
        for (bool bvh : {true, false}) {
            std::string data;
            for (long n : objectsOf(rows, series))
                if (const GrowthRow* r = findGrowthRow(rows, series, bvh, n); r && r->frameMs > 0)
                    data += std::to_string(n) + "\t" + shortestExact(r->frameMs) + "\n";
            line(series + (bvh ? ": frame, BVH" : ": frame, linear search"), data,
                 colours[(2 * s + (bvh ? 0 : 1)) % 4], false);
        }
        std::string build;
        for (long n : objectsOf(rows, series))
            if (const GrowthRow* r = findGrowthRow(rows, series, true, n); r && r->buildMs > 0)
                build += std::to_string(n) + "\t" + shortestExact(r->buildMs) + "\n";
        line(series + ": BVH build (CPU)", build, colours[(2 * s) % 4], true);
        ++s;
    }
    const fs::path image = tmp.path() / "plot.png";
    std::string script = pngTerminal(image);
    script += "set title " + gpString(title) + " font ',14'\n";
    script += "set xlabel 'objects (mesh triangles or spheres)'\n";
    script += "set ylabel 'time (ms)'\n";
    script += logAxes(double(minN) / 1.5, double(maxN) * 1.5, minMs / 1.6, maxMs * 1.6);
    script += "set grid xtics ytics lc rgb '#dddddd'\n";
    script += "set key top left box opaque\n";
    script += "set datafile separator '\\t'\n";
    script += plot + "\n";
    runGnuplot(gnuplot, script, image, pngPath, what);
}

void writeGrowthFiles(const std::vector<GrowthRow>& rows, const fs::path& dir,
                      const std::string& title, const std::string& commandLine,
                      const std::string& notes, bool plot) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw Error("cannot make the folder " + displayPath(dir) +
                    (ec ? ": " + ec.message() : std::string()));
    writeTextFileAtomic(dir / "growth.csv", growthCsv(rows));
    writeTextFileAtomic(dir / "growth.md",
                        growthMarkdown(rows, title, commandLine, notes, plot ? "growth.png" : ""));
    if (plot) writeGrowthPlot(rows, dir / "growth.png", title);
}

}  // namespace raylab
