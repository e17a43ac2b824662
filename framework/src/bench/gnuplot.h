#pragma once
// Running gnuplot for the bench plots (bench.png, fur.png): quoting, tics,
// and the child process. Shared by the plot writers of this folder.
#include <filesystem>
#include <string>

namespace raylab::bench {

// A gnuplot single-quoted string: only the quote itself is special there.
std::string gpString(const std::string& raw);
// A point label as a tab-separated data field: no tabs, and no double quote.
std::string gpLabel(const std::string& raw);
// "%g" text for tic marks and labels: 0.0001, 20, 1e-06.
std::string tidy(double x);
// A log axis's tics from LO to HI: 1, 2, 5 per decade when that gives at most
// a dozen, otherwise one per decade; "" when there are none.
std::string logTics(double lo, double hi);
// Log-scaled x and y axes over [X0, X1] x [Y0, Y1] with logTics' tics.
std::string logAxes(double x0, double x1, double y0, double y1);
// The PNG terminal lines every plot starts with (1280x800, pngcairo when there).
std::string pngTerminal(const std::filesystem::path& image);

// A private folder (mkdtemp, mode 0700) removed with everything in it when
// the object goes away.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

void writeBytes(const std::filesystem::path& file, const std::string& bytes);

// Whether GNUPLOT (a name on $PATH, or a path) can be run: checked before a
// long measurement whose report ends in a plot.
bool gnuplotAvailable(const std::string& gnuplot = "gnuplot");

// Runs GNUPLOT (a name looked up on $PATH, or a path) on SCRIPT, which must
// write the picture to IMAGE, and writes that picture to PNGPATH atomically.
// Throws Error("gnuplot not found: ...") when it is not there, and
// Error(WHAT + "gnuplot ...: its last message") when it fails.
void runGnuplot(const std::string& gnuplot, const std::string& script,
                const std::filesystem::path& image, const std::filesystem::path& pngPath,
                const std::string& what);

}  // namespace raylab::bench
