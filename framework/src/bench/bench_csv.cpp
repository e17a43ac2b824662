// bench.csv (bench_report.h).
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

#include "csv_text.h"

namespace raylab {

using namespace bench;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------- CSV

std::string csvNumber(double x) {
    if (std::isnan(x)) return "";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return shortestExact(x);
}

}  // namespace

// ---------------------------------------------------------------- CSV

std::string benchCsv(const std::vector<BenchRow>& rows) {
    const std::string eol = "\r\n";
    std::string out = "scene,width,height,depth,shadows,torus_solver,bvh,specialized,numerics,"
                      "frame_ms,compile_ms,rmse,psnr,max_err,"
                      "bad_px_share,depth_err_p99_ulp,engine,lever,rays,pareto" +
                      eol;
    const std::vector<std::size_t> front = paretoFront(rows);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const BenchRow& r = rows[i];
        const bool pareto = std::binary_search(front.begin(), front.end(), i);
        out += csvText(r.scene) + "," + std::to_string(r.width) + "," + std::to_string(r.height) +
               "," + std::to_string(r.depth) + "," + (r.shadows ? "1" : "0") + "," +
               csvText(r.torusSolver) + "," + (r.bvh ? "1" : "0") + "," +
               (r.specialized ? "1" : "0") + "," + csvText(r.numerics) + "," +
               csvNumber(r.frameMs) + "," + csvNumber(r.compileMs) + "," + csvNumber(r.rmse) + "," +
               csvNumber(r.psnr) + "," + csvNumber(r.maxErr) + "," + csvNumber(r.badPxShare) + "," +
               csvNumber(r.depthErrP99Ulp) + "," + csvText(r.engine) + "," + csvText(r.lever) +
               "," + std::to_string(r.rays) + "," + (pareto ? "1" : "0") + eol;
    }
    return out;
}

}  // namespace raylab
