// fur.csv, fur.md and fur.png (fur_report.h).
#include "fur_report.h"

#include "atomic_file.h"
#include "csv_text.h"
#include "error.h"
#include "gnuplot.h"
#include "measured_cells.h"
#include "paths.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace raylab {

using namespace bench;
namespace fs = std::filesystem;

namespace {

// The series in the order they first appear, and the triangle counts.
std::vector<std::string> furSeries(const std::vector<FurRow>& rows) {
    std::vector<std::string> names;
    for (const FurRow& r : rows)
        if (std::find(names.begin(), names.end(), furSeriesName(r)) == names.end())
            names.push_back(furSeriesName(r));
    return names;
}

std::set<long> trianglesOf(const std::vector<FurRow>& rows) {
    std::set<long> t;
    for (const FurRow& r : rows) t.insert(r.triangles);
    return t;
}

const FurRow* findFurRow(const std::vector<FurRow>& rows, const std::string& series,
                         long triangles) {
    for (const FurRow& r : rows)
        if (r.triangles == triangles && furSeriesName(r) == series) return &r;
    return nullptr;
}

std::string mib(std::size_t bytes) { return significant(double(bytes) / (1024.0 * 1024.0), 3); }

// The default series of each technique for the ratio table: the most shells
// measured with fins (the look the scenes are tuned for).
std::string shellsAndFinsSeries(const std::vector<FurRow>& rows) {
    int most = 0;
    for (const FurRow& r : rows)
        if (r.technique == "shells_and_fins" && r.fins) most = std::max(most, r.shells);
    return most ? "shells+fins " + std::to_string(most) : "";
}

}  // namespace

std::string furSeriesName(const FurRow& r) {
    if (r.technique == "fur_shader") return "fur shader";
    return std::string(r.fins ? "shells+fins " : "shells ") + std::to_string(r.shells);
}

std::string furCsv(const std::vector<FurRow>& rows) {
    const std::string eol = "\r\n";
    std::string out = "technique,mesh,triangles,shells,fins,frame_ms,buffer_bytes,rss_bytes,rmse,"
                      "bad_px_share" +
                      eol;
    for (const FurRow& r : rows)
        out += csvText(r.technique) + "," + csvText(r.mesh) + "," + std::to_string(r.triangles) +
               "," + std::to_string(r.shells) + "," + (r.fins ? "1" : "0") + "," +
               measuredCsv(r.frameMs) + "," + std::to_string(r.bufferBytes) + "," +
               std::to_string(r.rssBytes) + "," + measuredCsv(r.rmse) + "," +
               measuredCsv(r.badPxShare) + eol;
    return out;
}

std::string furMarkdown(const std::vector<FurRow>& rows, const std::string& title,
                        const std::string& commandLine, const std::string& notes,
                        const std::string& plotFile) {
    std::string md = "# " + title + "\n\n";
    if (!commandLine.empty()) md += "Made by `" + commandLine + "`.\n\n";
    if (!notes.empty()) md += notes + "\n\n";
    if (!plotFile.empty()) md += "![frame time against triangles](" + plotFile + ")\n\n";

    const std::vector<std::string> series = furSeries(rows);
    const std::set<long> triangles = trianglesOf(rows);
    md += "## Frame time (ms, median) by triangle count\n\n| triangles |";
    for (const std::string& s : series) md += " " + s + " |";
    md += "\n| ---: |";
    for (std::size_t i = 0; i < series.size(); ++i) md += " ---: |";
    md += "\n";
    for (long t : triangles) {
        md += "| " + std::to_string(t) + " |";
        for (const std::string& s : series) {
            const FurRow* r = findFurRow(rows, s, t);
            md += " " + (r ? measuredMs(r->frameMs) : std::string("-")) + " |";
        }
        md += "\n";
    }

    const std::string base = shellsAndFinsSeries(rows);
    if (!base.empty() && std::find(series.begin(), series.end(), "fur shader") != series.end()) {
        md += "\n## The fur shader against " + base +
              "\n\n"
              "| triangles | " +
              base +
              " (ms) | fur shader (ms) | fur shader / shells+fins |\n"
              "| ---: | ---: | ---: | ---: |\n";
        for (long t : triangles) {
            const FurRow* a = findFurRow(rows, base, t);
            const FurRow* b = findFurRow(rows, "fur shader", t);
            if (!a || !b) continue;
            md += "| " + std::to_string(t) + " | " + measuredMs(a->frameMs) + " | " +
                  measuredMs(b->frameMs) + " | " + significant(b->frameMs / a->frameMs, 3) +
                  "x |\n";
        }
    }

    md += "\n## Quality: each setting against the reference picture\n\n"
          "| triangles | series | RMSE (1/255 steps) | pixels off (%) |\n| ---: | --- | ---: | "
          "---: |\n";
    for (long t : triangles)
        for (const std::string& s : series) {
            const FurRow* r = findFurRow(rows, s, t);
            if (!r) continue;
            md += "| " + std::to_string(t) + " | " + s + " | " +
                  (std::isfinite(r->rmse) ? significant(r->rmse * 255.0, 3) : "-") + " | " +
                  (std::isfinite(r->badPxShare) ? significant(r->badPxShare * 100.0, 3) : "-") +
                  " |\n";
        }

    md += "\n## Memory\n\n| triangles | series | GPU buffers and textures (MiB) | process "
          "resident (MiB) |\n| ---: | --- | ---: | ---: |\n";
    for (long t : triangles)
        for (const std::string& s : series) {
            const FurRow* r = findFurRow(rows, s, t);
            if (!r) continue;
            md += "| " + std::to_string(t) + " | " + s + " | " + mib(r->bufferBytes) + " | " +
                  mib(r->rssBytes) + " |\n";
        }
    return md;
}

void writeFurPlot(const std::vector<FurRow>& rows, const fs::path& pngPath,
                  const std::string& title, const std::string& gnuplot) {
    const std::string what = "cannot plot " + displayPath(pngPath) + ": ";
    double minMs = INFINITY, maxMs = 0;
    long minT = 0, maxT = 0;
    for (const FurRow& r : rows) {
        if (!(r.frameMs > 0) || !std::isfinite(r.frameMs) || r.triangles <= 0) continue;
        minMs = std::min(minMs, r.frameMs);
        maxMs = std::max(maxMs, r.frameMs);
        minT = minT ? std::min(minT, r.triangles) : r.triangles;
        maxT = std::max(maxT, r.triangles);
    }
    if (maxMs == 0) throw Error(what + "no row has a measured frame time");
    static const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                          "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    TempDir tmp;
    std::string plot;
    const std::vector<std::string> series = furSeries(rows);
    for (std::size_t s = 0; s < series.size(); ++s) {
        std::string data;
        for (long t : trianglesOf(rows))
            if (const FurRow* r = findFurRow(rows, series[s], t); r && r->frameMs > 0)
                data += std::to_string(t) + "\t" + shortestExact(r->frameMs) + "\n";
        if (data.empty()) continue;
        const fs::path file = tmp.path() / ("series" + std::to_string(s) + ".dat");
        writeBytes(file, data);
        plot += (plot.empty() ? "plot " : ", \\\n     ") + gpString(file.string()) +
                " using 1:2 with linespoints pt 7 ps 1.3 lw 2 lc rgb '" +
                colours[s % std::size(colours)] + "' title " + gpString(series[s]);
    }
    const fs::path image = tmp.path() / "plot.png";
    const double x0 = double(minT) / 1.5, x1 = double(maxT) * 1.5, y0 = minMs / 1.6,
                 y1 = maxMs * 1.6;
    std::string script = pngTerminal(image);
    script += "set title " + gpString(title) + " font ',14'\n";
    script += "set xlabel 'triangles in the mesh'\n";
    script += "set ylabel 'frame time (ms, median)'\n";
    script += logAxes(x0, x1, y0, y1);
    script += "set grid xtics ytics lc rgb '#dddddd'\n";
    script += "set key top left box opaque\n";
    script += "set datafile separator '\\t'\n";
    script += plot + "\n";
    runGnuplot(gnuplot, script, image, pngPath, what);
}

void writeFurFiles(const std::vector<FurRow>& rows, const fs::path& dir, const std::string& title,
                   const std::string& commandLine, const std::string& notes, bool plot) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw Error("cannot make the folder " + displayPath(dir) +
                    (ec ? ": " + ec.message() : std::string()));
    writeTextFileAtomic(dir / "fur.csv", furCsv(rows));
    writeTextFileAtomic(dir / "fur.md",
                        furMarkdown(rows, title, commandLine, notes, plot ? "fur.png" : ""));
    if (plot) writeFurPlot(rows, dir / "fur.png", title);
}

}  // namespace raylab
