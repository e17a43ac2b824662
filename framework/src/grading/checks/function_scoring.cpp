// Scoring a harness run: each case's result against its double-precision
// reference, through the spec's own comparison.
#include "error.h"
#include "function_checks.h"

namespace raylab {

std::vector<glm::dvec4> referenceWants(const FunctionSpec& spec) {
    if (!spec.reference)
        throw Error("function check " + spec.name +
                    ": this build carries no references (the page's core reads the expected "
                    "values from web/function_tables.json)");
    std::vector<glm::dvec4> wants;
    for (const FunctionCase& c : spec.cases) wants.push_back(spec.reference(c));
    return wants;
}

FunctionOutcome scoreFunctionResults(const FunctionSpec& spec,
                                     const std::vector<glm::vec4>& results) {
    return scoreFunctionResults(spec, results, referenceWants(spec));
}

FunctionOutcome scoreFunctionResults(const FunctionSpec& spec,
                                     const std::vector<glm::vec4>& results,
                                     const std::vector<glm::dvec4>& wants) {
    if (wants.size() != spec.cases.size())
        throw Error("function check " + spec.name + ": " + std::to_string(wants.size()) +
                    " expected values for " + std::to_string(spec.cases.size()) + " cases");
    if (results.size() != spec.cases.size())
        throw Error("function check " + spec.name + ": " + std::to_string(results.size()) +
                    " results for " + std::to_string(spec.cases.size()) + " cases");
    FunctionOutcome out;
    out.name = spec.name;
    out.total = int(spec.cases.size());
    CaseVerdicts verdicts;
    bool todo = false;
    for (std::size_t i = 0; i < spec.cases.size(); ++i) {
        const FunctionCase& c = spec.cases[i];
        const glm::vec4& r = results[i];
        todo = todo || r.w == kHarnessTodoMarker;
        std::string why = r.w == kHarnessTodoMarker ? c.label + ": reaches an unfinished TODO"
                                                    : spec.compare(c, glm::dvec4(r), wants[i]);
        verdicts.push_back({&c, glm::dvec4(r), wants[i], !why.empty()});
        if (why.empty()) ++out.passed;
        else if (out.firstFailure.empty()) out.firstFailure = why;
    }
    // A stub's answers prove nothing about a cause.
    if (out.passed < out.total && !todo)
        for (const FunctionDiagnosis& d : spec.diagnoses)
            if (d.applies(verdicts)) {
                out.cause = d.cause;
                break;
            }
    return out;
}

}  // namespace raylab
