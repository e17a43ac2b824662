#include "gnuplot.h"

#include "atomic_file.h"
#include "bench_rows.h"
#include "child_process.h"
#include "error.h"
#include "text_format.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace raylab::bench {

namespace fs = std::filesystem;

namespace {

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

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
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

}  // namespace

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

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << bytes;
    out.close();
    if (!out) throw Error("cannot write temporary file " + file.string());
}

TempDir::TempDir() {
    std::error_code ec;
    fs::path base = fs::temp_directory_path(ec);
    if (ec) base = "/tmp";
    std::string pattern = (base / "raylab-bench-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
        throw Error("cannot create a temporary folder in " + base.string() + ": " +
                    std::strerror(errno));
    path_ = pattern;
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::string logAxes(double x0, double x1, double y0, double y1) {
    std::string script = "set logscale xy\n";
    script += "set xrange [" + shortestExact(x0) + ":" + shortestExact(x1) + "]\n";
    script += "set yrange [" + shortestExact(y0) + ":" + shortestExact(y1) + "]\n";
    if (const std::string tics = logTics(x0, x1); !tics.empty())
        script += "set xtics " + tics + "\n";
    if (const std::string tics = logTics(y0, y1); !tics.empty())
        script += "set ytics " + tics + "\n";
    return script;
}

std::string pngTerminal(const fs::path& image) {
    return "set encoding utf8\n"
           "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
           "  set terminal pngcairo size 1280,800 noenhanced font 'sans,11'\n"
           "} else {\n"
           "  set terminal png size 1280,800 noenhanced\n"
           "}\n"
           "set output " +
           gpString(image.string()) + "\n";
}

bool gnuplotAvailable(const std::string& gnuplot) { return !findExecutable(gnuplot).empty(); }

void runGnuplot(const std::string& gnuplot, const std::string& script, const fs::path& image,
                const fs::path& pngPath, const std::string& what) {
    const std::string exe = findExecutable(gnuplot);
    if (exe.empty())
        throw Error("gnuplot not found: install gnuplot-nox (bash install.sh --test does)");
    const fs::path dir = image.parent_path();
    const fs::path scriptFile = dir / "plot.gp";
    writeBytes(scriptFile, script);
    // -d: no ~/.gnuplot or system init file, so a user's settings cannot
    // change the picture.
    const fs::path log = dir / "gnuplot.log";
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

}  // namespace raylab::bench
