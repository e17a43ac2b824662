#include "numerics_support.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>

namespace raylab::numerics {

double floatUlp(double x) {
    float f = std::fabs(float(x));
    return double(std::nextafter(f, std::numeric_limits<float>::infinity()) - f);
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    std::size_t i = std::size_t(std::ceil(p / 100.0 * double(values.size())));
    return values[std::min(values.size() - 1, i == 0 ? 0 : i - 1)];
}

std::vector<glm::vec4> runSolution(const FunctionSpec& spec, const std::string& stageId,
                                   const std::vector<std::string>& extraDefines) {
    ensureGlContext();
    const StageInfo& stage = findStage(stageId);
    StageSources sources = solutionSources(stage);
    // The tests' own GLSL helpers (glsl/), found before the solution's files.
    sources.search.insert(sources.search.begin(),
                          std::filesystem::path(RAYLAB_SOURCE_DIR) / "tests" / "numerics" / "glsl");
    // The harness draws one pixel per case in a single row: long tables go
    // in pieces that fit every driver's texture and framebuffer width.
    constexpr std::size_t kChunk = 8192;
    if (spec.cases.size() <= kChunk) return runHarness(spec, stage, sources, extraDefines);
    std::vector<glm::vec4> all;
    FunctionSpec piece = spec;
    for (std::size_t first = 0; first < spec.cases.size(); first += kChunk) {
        std::size_t last = std::min(spec.cases.size(), first + kChunk);
        piece.cases.assign(spec.cases.begin() + std::ptrdiff_t(first),
                           spec.cases.begin() + std::ptrdiff_t(last));
        std::vector<glm::vec4> got = runHarness(piece, stage, sources, extraDefines);
        all.insert(all.end(), got.begin(), got.end());
    }
    return all;
}

}  // namespace raylab::numerics
