// bench.png: the speed-vs-error plot, drawn by gnuplot in a child process (bench_report.h).
#include "bench_report.h"
#include "bench_rows.h"

#include "atomic_file.h"
#include "error.h"
#include "paths.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "child_process.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab {

using namespace bench;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------- gnuplot

// A gnuplot single-quoted string: only the quote itself is special there.
std::string gpString(const std::string& raw) {
    std::string out = "'";
    for (char c : oneLine(raw)) {
        if (c == '\'') out += '\'';
        out += c;
    }
    return out + "'";
}

// A point label as a tab-separated data field: no tabs, and no double quote
// (gnuplot would read a quoted field).
std::string gpLabel(const std::string& raw) {
    std::string out = oneLine(raw);
    std::replace(out.begin(), out.end(), '"', '\'');
    return out;
}

// One colour per scene, told apart in print and by most colour-blind readers
// (Tableau 10's first eight), cycled after that.
const char* sceneColour(std::size_t i) {
    static const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                          "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    return colours[i % std::size(colours)];
}

// NAME on $PATH (or NAME itself when it has a '/'), as execv wants it; empty
// when there is no such executable file. Empty $PATH entries are skipped
// rather than read as "the current folder": the plot must not run whatever
// lies there.
std::string findExecutable(const std::string& name) {
    auto runnable = [](const std::string& p) {
        struct stat st {};
        return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
    };
    if (name.empty()) return "";
    if (name.find('/') != std::string::npos) return runnable(name) ? name : "";
    const char* env = std::getenv("PATH");
    std::stringstream dirs(env ? env : "/usr/local/bin:/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        if (dir.empty()) continue;
        const std::string candidate = dir + "/" + name;
        if (runnable(candidate)) return candidate;
    }
    return "";
}

// A private folder (mkdtemp, mode 0700) removed with everything in it when
// the object goes away.
class TempDir {
public:
    TempDir() {
        std::error_code ec;
        fs::path base = fs::temp_directory_path(ec);
        if (ec) base = "/tmp";
        std::string pattern = (base / "raylab-bench-XXXXXX").string();
        if (!::mkdtemp(pattern.data()))
            throw Error("cannot create a temporary folder in " + base.string() + ": " +
                        std::strerror(errno));
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << bytes;
    out.close();
    if (!out) throw Error("cannot write temporary file " + file.string());
}

// The last non-empty line of gnuplot's output: its error message (the lines
// before it repeat the script line and point at the column).
std::string lastLine(const std::string& log) {
    std::stringstream in(log);
    std::string line, last;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    return oneLine(last);
}

// "%g" text for tic marks and labels: 0.0001, 20, 1e-06.
std::string tidy(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

// A log axis's tics from LO to HI: 1, 2, 5 per decade when that gives at most
// a dozen (gnuplot alone would label a 9..210 ms axis at 10 and 100 only),
// otherwise one per decade.
std::string logTics(double lo, double hi) {
    std::vector<double> tics;
    for (int step : {3, 1}) {
        tics.clear();
        for (int e = int(std::floor(std::log10(lo))); e <= int(std::ceil(std::log10(hi))); ++e)
            for (double m : {1.0, 2.0, 5.0}) {
                if (step == 1 && m != 1.0) continue;
                const double t = m * std::pow(10.0, e);
                if (t >= lo && t <= hi) tics.push_back(t);
            }
        if (tics.size() <= 12) break;
    }
    std::string out;
    for (double t : tics)
        out += (out.empty() ? "(" : ", ") + gpString(tidy(t)) + " " + shortestExact(t);
    return out.empty() ? "" : out + ")";
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

    const std::string exe = findExecutable(gnuplot);
    if (exe.empty()) throw Error("gnuplot not found: install gnuplot-nox (install.sh does)");

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
    std::string script;
    script += "set encoding utf8\n";
    script += "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
              "  set terminal pngcairo size 1280,800 noenhanced font 'sans,11'\n"
              "} else {\n"
              "  set terminal png size 1280,800 noenhanced\n"
              "}\n";
    script += "set output " + gpString(image.string()) + "\n";
    script += "set title " + gpString(title) + " font ',14'\n";
    script += "set xlabel 'frame time (ms)'\n";
    script += "set ylabel 'RMSE vs double reference (0..1)'\n";
    script += "set logscale xy\n";
    const double x0 = minMs / 1.6, x1 = maxMs * 4.0, y0 = lowY / 3.0, y1 = highY * 3.0;
    script += "set xrange [" + shortestExact(x0) + ":" + shortestExact(x1) + "]\n";
    script += "set yrange [" + shortestExact(y0) + ":" + shortestExact(y1) + "]\n";
    if (const std::string tics = logTics(x0, x1); !tics.empty())
        script += "set xtics " + tics + "\n";
    if (const std::string tics = logTics(y0, y1); !tics.empty())
        script += "set ytics " + tics + "\n";
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
    const fs::path scriptFile = tmp.path() / "plot.gp";
    writeBytes(scriptFile, script);

    // -d: no ~/.gnuplot or system init file, so a user's settings cannot
    // change the picture.
    const fs::path log = tmp.path() / "gnuplot.log";
    Child child({exe, "-d", scriptFile.string()}, log, ChildLimits{60.0, 2048});
    const ChildOutcome& outcome = child.wait();
    const std::string bytes = readBytes(image);
    if (outcome.timedOut || outcome.signal || outcome.exitCode != 0) {
        const std::string message = lastLine(readBytes(log));
        throw Error(what + "gnuplot " + outcome.describe() +
                    (message.empty() ? "" : ": " + message));
    }
    if (bytes.size() < 8 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
        throw Error(what + "gnuplot wrote no PNG file");
    // writeTextFileAtomic writes bytes as they are: FILE.tmp-PID, fsync, rename.
    writeTextFileAtomic(pngPath, bytes);
}

}  // namespace raylab
