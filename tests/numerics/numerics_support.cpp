#include "numerics_support.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab::numerics {

void ensureGlContext() {
    static std::unique_ptr<GlContext> context = createHeadlessContext(Backend::Auto);
}

double floatUlp(double x) {
    float f = std::fabs(float(x));
    return double(std::nextafter(f, std::numeric_limits<float>::infinity()) - f);
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    std::size_t i = std::size_t(std::ceil(p / 100.0 * double(values.size()))) ;
    return values[std::min(values.size() - 1, i == 0 ? 0 : i - 1)];
}

std::vector<glm::vec4> runSolution(const FunctionSpec& spec, const std::string& stageId, const std::vector<std::string>& extraDefines) {
    ensureGlContext();
    const StageInfo& stage = findStage(stageId);
    return runHarness(spec, stage, solutionSources(stage), extraDefines);
}

} // namespace raylab::numerics
