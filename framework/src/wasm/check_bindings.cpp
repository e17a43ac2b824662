// The page's checks through the core (embind): the function checks' harness
// programs, case inputs and scoring (grading/checks), and the comparison of
// a check view with its reference picture (core/image_compare.h), so the page
// judges with native's tables, references, thresholds and hints. The page
// only draws (web/src). Students need not read this file.
#include "embind_support.h"
#include "error.h"
#include "function_checks.h"
#include "harness_program.h"
#include "image_compare.h"
#include "stage_catalog.h"
#include "stage_sources.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

using emscripten::val;
using nlohmann::json;

namespace raylab {

namespace {

// A stage's function checks, for the lab in LAB (empty: the solution).
class FunctionChecks {
public:
    explicit FunctionChecks(const std::string& requestJson) {
        try {
            const json r = json::parse(requestJson);
            stage_ = &findStage(r.value("stage", ""));
            const std::string lab = r.value("lab", "");
            sources_ = lab.empty() ? solutionSources(*stage_) : labSources(*stage_, lab);
            specs_ = functionSpecsFor(*stage_);
        } catch (const std::exception& e) { error_ = e.what(); }
    }
    std::string error() const { return error_; }

    // Per function: its name, case count, the uniforms each case sets, and
    // its harness program in GLSL ES 3.00, or the one-line reason it could
    // not be assembled (native: "does not compile: ...").
    std::string list() const {
        json out = json::array();
        for (const FunctionSpec* spec : specs_) {
            json f = {{"name", spec->name},
                      {"cases", spec->cases.size()},
                      {"perCase", harnessDrawsPerCase(*spec)}};
            json uniforms = json::array();
            for (const FunctionCase& c : spec->cases) uniforms.push_back(c.uniforms);
            f["uniforms"] = uniforms;
            try {
                const HarnessProgram p = assembleHarness(*spec, *stage_, sources_, {}, true);
                f["vertex"] = sourceJson(p.vertex);
                f["fragment"] = sourceJson(p.fragment);
            } catch (const std::exception& e) { f["error"] = e.what(); }
            out.push_back(f);
        }
        return out.dump();
    }

    // uCases' texels for NAME: RGBA floats, one column per case, 4 rows.
    val texels(const std::string& name) const {
        return typedArray("Float32Array", harnessCaseTexels(spec(name)));
    }

    // What the harness wrote (RGBA floats, one pixel per case) scored as
    // natively: {name, passed, total, firstFailure}.
    std::string score(const std::string& name, const val& floats) const {
        try {
            const std::vector<float> raw = emscripten::convertJSArrayToNumberVector<float>(floats);
            std::vector<glm::vec4> results;
            for (std::size_t i = 0; i + 3 < raw.size(); i += 4)
                results.emplace_back(raw[i], raw[i + 1], raw[i + 2], raw[i + 3]);
            const FunctionOutcome o = scoreFunctionResults(spec(name), results);
            return json{{"name", o.name},
                        {"passed", o.passed},
                        {"total", o.total},
                        {"firstFailure", o.firstFailure}}
                .dump();
        } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
    }

private:
    const FunctionSpec& spec(const std::string& name) const {
        for (const FunctionSpec* s : specs_)
            if (s->name == name) return *s;
        throw Error("stage " + (stage_ ? stage_->id : std::string("?")) +
                    " has no function check '" + name + "'");
    }
    const StageInfo* stage_ = nullptr;
    StageSources sources_;
    std::vector<const FunctionSpec*> specs_;
    std::string error_;
};

Image imageFrom(const val& rgba, int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgba = emscripten::convertJSArrayToNumberVector<std::uint8_t>(rgba);
    if (image.rgba.size() != std::size_t(width) * std::size_t(height) * 4)
        throw Error("an image of " + std::to_string(width) + "x" + std::to_string(height) +
                    " needs " + std::to_string(width * height * 4) + " bytes, got " +
                    std::to_string(image.rgba.size()));
    return image;
}

// MINE against EXPECTED (RGBA bytes, WIDTH x HEIGHT, the same row order) with
// native's tolerance and hints. CONTEXTJSON: {stage, todoPixels, nonFinite}.
// Answers {passed, badShare, maxDiff, sameSize, description, hint}.
std::string compareView(const val& mine, const val& expected, int width, int height,
                        const std::string& contextJson) {
    try {
        const json c = json::parse(contextJson);
        const StageInfo& stage = findStage(c.value("stage", ""));
        const Image a = imageFrom(mine, width, height), b = imageFrom(expected, width, height);
        const CompareTolerance tolerance;
        const ImageDiff diff = compareImages(a, b, tolerance.channel);
        const long nonFinite = c.value("nonFinite", 0L);
        const bool passed = imagesAgree(diff, tolerance) && nonFinite == 0;
        const std::string hint = passed ? std::string()
                                        : diagnose(a, b, tolerance.channel,
                                                   {stage.hintDarker, stage.hintBrighter,
                                                    c.value("todoPixels", 0L), nonFinite});
        return json{
            {"passed", passed},          {"badShare", diff.badShare},     {"maxDiff", diff.maxDiff},
            {"sameSize", diff.sameSize}, {"description", describe(diff)}, {"hint", hint}}
            .dump();
    } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
}

// Native's heat map of the difference (black = equal, red = max), RGBA bytes.
val heatMap(const val& mine, const val& expected, int width, int height) {
    return typedArray(
        "Uint8Array",
        diffHeatMap(imageFrom(mine, width, height), imageFrom(expected, width, height)).rgba);
}

}  // namespace

}  // namespace raylab

EMSCRIPTEN_BINDINGS(raylab_checks) {
    emscripten::function("compareView", &raylab::compareView);
    emscripten::function("heatMap", &raylab::heatMap);
    using raylab::FunctionChecks;
    emscripten::class_<FunctionChecks>("FunctionChecks")
        .constructor<std::string>()
        .function("error", &FunctionChecks::error)
        .function("list", &FunctionChecks::list)
        .function("texels", &FunctionChecks::texels)
        .function("score", &FunctionChecks::score);
}
