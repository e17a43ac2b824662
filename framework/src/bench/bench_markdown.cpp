// bench.md (bench_report.h).
#include "bench_report.h"
#include "bench_rows.h"

#include "atomic_file.h"
#include "error.h"
#include "paths.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace raylab {

using namespace bench;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------- Markdown

// Table cell text: one line, Markdown's active characters escaped (a '|'
// would end the cell).
std::string mdText(const std::string& raw) {
    std::string out;
    for (char c : oneLine(raw)) {
        if (std::strchr("\\`*_[]<>|~#", c)) out += '\\';  // no NUL here: oneLine made it a space
        out += c;
    }
    return out;
}

// TEXT as an inline code span: a fence longer than any run of backticks in
// it, padded with spaces when it starts or ends with one.
std::string mdCode(const std::string& raw) {
    const std::string text = oneLine(raw);
    std::size_t longest = 0, run = 0;
    for (char c : text) {
        run = c == '`' ? run + 1 : 0;
        longest = std::max(longest, run);
    }
    const std::string fence(longest + 1, '`');
    const bool pad = !text.empty() && (text.front() == '`' || text.back() == '`');
    return fence + (pad ? " " : "") + text + (pad ? " " : "") + fence;
}

std::string mdNumber(double x, int decimals, double scale = 1.0) {
    if (std::isnan(x)) return "n/a";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return fixedPoint(x * scale, decimals);
}

// Three significant digits, for the RMSE as a plain number (0.00123).
std::string mdSignificant(double x) {
    if (std::isnan(x)) return "n/a";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return significant(x, 3);
}

const char* yesNo(bool b) { return b ? "yes" : "no"; }

}  // namespace

// ---------------------------------------------------------------- Markdown

std::string benchMarkdown(const std::vector<BenchRow>& rows, const std::string& title,
                          const std::string& commandLine, const std::string& plotFile) {
    std::string out = "# " + mdText(title) + "\n\n";
    out += "Made by " + mdCode(commandLine) + "\n\n";
    if (rows.empty()) return out + "No rows were measured.\n";
    if (!plotFile.empty())
        out += "![frame time against RMSE, one colour per scene](" + plotFile + ")\n\n";
    out +=
        "Errors are against a double-precision reference: RMSE and max error in 1/255 steps of an "
        "8-bit colour "
        "(and RMSE as a number in 0..1), bad px = share of pixels that differ visibly. "
        "**Pareto** rows: no other setting of the same scene is both faster and more accurate.\n";

    const std::vector<std::size_t> front = paretoFront(rows);
    for (auto& entry : byScene(rows)) {
        // (Named, not a structured binding: clang 14, which builds the
        // sanitizer build, lets no lambda capture one.)
        const std::string& scene = entry.first;
        std::vector<std::size_t>& indices = entry.second;
        sortByFrameTime(indices, rows);
        // The scene's Embree rows: a row's time as a multiple of the one that
        // cast its rays (the same lever; the baseline's rays have none).
        auto embreeFor = [&](const BenchRow& r) -> const BenchRow* {
            for (std::size_t i : indices)
                if (rows[i].engine == "embree" && rows[i].lever == rayLever(r.lever) &&
                    rows[i].width == r.width && rows[i].height == r.height &&
                    rows[i].depth == r.depth && rows[i].shadows == r.shadows)
                    return &rows[i];
            return nullptr;
        };
        out += "\n## " + mdText(scene) + "\n\n";
        out += "| Pareto | Setting | Size | Depth | Shadows | Torus solver | BVH | Specialized | "
               "Numerics | Frame (ms) | x Embree | "
               "Compile (ms) | RMSE (1/255) | RMSE | PSNR (dB) | Max err (1/255) | Bad px | Depth "
               "err p99 (ulp) |\n";
        out += "| :---: | --- | --- | ---: | --- | --- | --- | --- | --- | ---: | ---: | ---: | "
               "---: | ---: | ---: | ---: | ---: | ---: |\n";
        for (std::size_t i : indices) {
            const BenchRow& r = rows[i];
            const BenchRow* embree = embreeFor(r);
            const bool pareto = std::binary_search(front.begin(), front.end(), i);
            const std::string name = mdText(benchSettingName(r));
            out += std::string("| ") + (pareto ? "**yes**" : "") + " | " +
                   (pareto ? "**" + name + "**" : name) + " | " + std::to_string(r.width) + "x" +
                   std::to_string(r.height) + " | " + std::to_string(r.depth) + " | " +
                   yesNo(r.shadows) + " | " + mdText(r.torusSolver) + " | " + yesNo(r.bvh) + " | " +
                   yesNo(r.specialized) + " | " + mdText(r.numerics) + " | " +
                   mdNumber(r.frameMs, 1) + " | " +
                   (embree ? mdNumber(r.frameMs / embree->frameMs, 2) : std::string("n/a")) +
                   " | " + mdNumber(r.compileMs, 1) + " | " + mdNumber(r.rmse, 2, 255.0) + " | " +
                   mdSignificant(r.rmse) + " | " + mdNumber(r.psnr, 1) + " | " +
                   mdNumber(r.maxErr, 1, 255.0) + " | " +
                   (std::isnan(r.badPxShare) ? "n/a" : mdNumber(r.badPxShare, 2, 100.0) + " %") +
                   " | " + mdNumber(r.depthErrP99Ulp, 1) + " |\n";
        }
        for (std::size_t i : indices) {
            const BenchRow& e = rows[i];
            if (e.engine != "embree") continue;
            const std::string name = mdText(benchSettingName(e));
            if (std::isnan(e.frameMs))
                out +=
                    "\n" + name + ": Embree not built (install libembree-dev, run cmake again).\n";
            else
                out += "\n" + name + ": Embree casting the " + std::to_string(e.rays) +
                       " rays of that frame (primary, reflected, refracted, glow and shadow rays, "
                       "exported from the reference tracer" +
                       (e.lever.empty() ? std::string("") : " with the same lever") +
                       ") on the same cores, no shading: " + mdNumber(e.frameMs, 1) +
                       " ms (its BVH build: " + mdNumber(e.compileMs, 1) + " ms).\n";
        }
        if (std::any_of(indices.begin(), indices.end(),
                        [&](std::size_t i) { return rows[i].engine == "embree"; }))
            out += "\n**x Embree**: a row's frame time over the time Embree takes to cast the "
                   "same rays (same size, depth, shadows and lever); n/a where Embree did not "
                   "cast that row's rays.\n";
    }
    return out;
}

}  // namespace raylab
