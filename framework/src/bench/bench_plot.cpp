// bench.png: the speed-vs-error plot, drawn by gnuplot in a child process (bench_report.h).
#include "bench_report.h"
#include "bench_rows.h"
#include "gnuplot.h"

#include "atomic_file.h"
#include "error.h"
#include "paths.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace raylab {

using namespace bench;
namespace fs = std::filesystem;

namespace {

// One colour per scene, told apart in print and by most colour-blind readers
// (Tableau 10's first eight), cycled after that.
const char* sceneColour(std::size_t i) {
    static const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                          "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    return colours[i % std::size(colours)];
}

// Data file text, "x<TAB>y" or "x<TAB>y<TAB>label" lines, for one scene.
struct PlotSeries {
    std::string points;     // all its plotted rows
    std::string front;      // its Pareto rows by frame time
    std::string labels[2];  // point labels drawn above / below their point
};

}  // namespace

// ---------------------------------------------------------------- plot

void writeBenchPlot(const std::vector<BenchRow>& rows, const fs::path& pngPath,
                    const std::string& title, const std::string& gnuplot) {
    const std::string what = "cannot plot " + displayPath(pngPath) + ": ";

    // Log axes cannot show a 0 ms frame or a NaN; RMSE 0 (exact) gets a floor
    // a decade below the smallest error there is, so that it still shows.
    auto plottable = [](const BenchRow& r) { return measured(r) && r.frameMs > 0; };
    double minRmse = INFINITY, maxRmse = 0, minMs = INFINITY, maxMs = 0;
    bool anyExact = false;
    for (const BenchRow& r : rows) {
        if (!plottable(r)) continue;
        minMs = std::min(minMs, r.frameMs);
        maxMs = std::max(maxMs, r.frameMs);
        maxRmse = std::max(maxRmse, r.rmse);
        if (r.rmse > 0) minRmse = std::min(minRmse, r.rmse);
        else anyExact = true;
    }
    if (maxMs == 0) throw Error(what + "no row has a measured frame time and RMSE");
    const double floorRmse =
        std::isfinite(minRmse) ? std::pow(10.0, std::floor(std::log10(minRmse)) - 1) : 1e-6;
    const double lowY = anyExact ? floorRmse : minRmse;
    const double highY = std::max(maxRmse, lowY);

    TempDir tmp;
    const std::vector<std::size_t> front = paretoFront(rows);
    const auto groups = byScene(rows);

    // One data file per scene and one for its front: a scene with nothing to
    // plot simply has no plot element (gnuplot fails on empty files).
    std::string plot;
    bool frontTitled = false;
    auto add = [&](const std::string& element) {
        plot += (plot.empty() ? "plot " : ", \\\n     ") + element;
    };
    std::vector<std::string> pointElements, labelElements, ringElements;
    for (std::size_t s = 0; s < groups.size(); ++s) {
        std::vector<std::size_t> indices = groups[s].second;
        sortByFrameTime(indices, rows);
        PlotSeries series;
        int n = 0;
        for (std::size_t i : indices) {
            const BenchRow& r = rows[i];
            if (!plottable(r)) continue;
            const std::string y = shortestExact(r.rmse > 0 ? r.rmse : floorRmse);
            // Labels alternate above and below their point so that the
            // neighbours along the x axis do not overwrite each other.
            const std::string label = gpLabel(benchSettingName(r) + (r.rmse > 0 ? "" : " (exact)"));
            series.points += shortestExact(r.frameMs) + "\t" + y + "\n";
            series.labels[n++ % 2] += shortestExact(r.frameMs) + "\t" + y + "\t" + label + "\n";
            if (std::binary_search(front.begin(), front.end(), i))
                series.front += shortestExact(r.frameMs) + "\t" + y + "\n";
        }
        if (series.points.empty()) continue;
        const std::string colour = sceneColour(s);
        const fs::path points = tmp.path() / ("scene" + std::to_string(s) + ".dat");
        writeBytes(points, series.points);
        pointElements.push_back(gpString(points.string()) +
                                " using 1:2 with points pt 7 ps 1.6 lc rgb '" + colour +
                                "' title " + gpString(groups[s].first));
        // Separate files rather than a filter: gnuplot 5.4.4 crashes on a
        // "with labels" plot whose points are all NaN.
        for (int half = 0; half < 2; ++half) {
            if (series.labels[half].empty()) continue;
            const fs::path file = tmp.path() / ("scene" + std::to_string(s) + "-labels" +
                                                std::to_string(half) + ".dat");
            writeBytes(file, series.labels[half]);
            labelElements.push_back(
                gpString(file.string()) + " using 1:2:3 with labels left offset char 1.2," +
                (half == 0 ? "0.7" : "-0.7") + " tc rgb '" + colour + "' notitle");
        }
        if (!series.front.empty()) {
            const fs::path frontFile = tmp.path() / ("scene" + std::to_string(s) + "-front.dat");
            writeBytes(frontFile, series.front);
            add(gpString(frontFile.string()) + " using 1:2 with steps lw 2 dt 1 lc rgb '" + colour +
                "' notitle");
            ringElements.push_back(
                gpString(frontFile.string()) +
                " using 1:2 with points pt 6 ps 2.8 lw 2 lc rgb '#333333' " +
                (frontTitled ? std::string("notitle")
                             : std::string("title 'Pareto front (ringed; step line per scene)'")));
            frontTitled = true;
        }
    }
    for (const auto* list : {&pointElements, &ringElements, &labelElements})
        for (const std::string& e : *list) add(e);

    // Room around the points on log axes: labels run to the right of theirs.
    const fs::path image = tmp.path() / "plot.png";
    std::string script = pngTerminal(image);
    script += "set title " + gpString(title) + " font ',14'\n";
    script += "set xlabel 'frame time (ms)'\n";
    script += "set ylabel 'RMSE vs double reference (0..1)'\n";
    const double x0 = minMs / 1.6, x1 = maxMs * 4.0, y0 = lowY / 3.0, y1 = highY * 3.0;
    script += logAxes(x0, x1, y0, y1);
    script += "set style line 100 lc rgb '#dddddd' lw 1 dt 1\n";
    script += "set grid xtics ytics ls 100\n";
    script += "set key top right box opaque samplen 2 spacing 1.2\n";
    script += "set datafile separator '\\t'\n";
    if (anyExact) {
        const std::string f = shortestExact(floorRmse);
        script += "set arrow from graph 0, first " + f + " to graph 1, first " + f +
                  " nohead dt 2 lc rgb '#888888'\n";
        script += "set label 'RMSE = 0 (exact), drawn at " + tidy(floorRmse) +
                  "' at graph 0.01, first " + f + " offset 0,-0.9 tc rgb '#666666'\n";
    }
    script += plot + "\n";
    runGnuplot(gnuplot, script, image, pngPath, what);
}

}  // namespace raylab
