// The page's checks through the core (embind): the function checks' harness
// programs, case inputs and scoring (grading/checks), and the comparison of
// a check view with its reference picture (core/image_compare.h), so the page
// judges with native's tables, references, thresholds and hints. The page
// only draws (web/src). Students need not read this file.
#include "check_report.h"
#include "embind_support.h"
#include "error.h"
#include "function_checks.h"
#include "function_tables.h"
#include "harness_program.h"
#include "image_compare.h"
#include "paths.h"
#include "stage_catalog.h"
#include "stage_score.h"
#include "stage_sources.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

using emscripten::val;
using nlohmann::json;

namespace raylab {

namespace {

// The expected values the checks score against and their harness GLSL (no
// reference code and no stand-in here): kTablesAsData (function_tables.h).
std::vector<glm::dvec4> wantsOf(const FunctionSpec& spec) {
    return tableOf(tablesAsData(), spec.name, kTablesAsData).wants;
}

// What a harness wrote (RGBA floats, one pixel per case), one vec4 per case.
std::vector<glm::vec4> harnessResults(const val& floats) {
    const std::vector<float> raw = emscripten::convertJSArrayToNumberVector<float>(floats);
    std::vector<glm::vec4> results;
    for (std::size_t i = 0; i + 3 < raw.size(); i += 4)
        results.emplace_back(raw[i], raw[i + 1], raw[i + 2], raw[i + 3]);
    return results;
}

json outcomeJson(const FunctionOutcome& o) {
    return {{"name", o.name},
            {"passed", o.passed},
            {"total", o.total},
            {"firstFailure", o.firstFailure}};
}

// A stage's function checks, for the lab in LAB (empty: the solution).
class FunctionChecks {
public:
    explicit FunctionChecks(const std::string& requestJson) {
        try {
            const json r = json::parse(requestJson);
            stage_ = &findStage(r.value("stage", ""));
            const std::string lab = r.value("lab", "");
            sources_ = lab.empty() ? solutionSources(*stage_) : labSources(*stage_, lab);
            for (const FunctionSpec* spec : functionSpecsFor(*stage_))
                specs_.push_back(withHarnessFrom(tablesAsData(), *spec, kTablesAsData));
        } catch (const std::exception& e) { error_ = e.what(); }
    }
    std::string error() const { return error_; }

    // Per function: its name, case count, the uniforms each case sets, and
    // its harness program in GLSL ES 3.00, or the one-line reason it could
    // not be assembled (native: "does not compile: ...").
    std::string list() const {
        json out = json::array();
        for (const FunctionSpec& spec : specs_) {
            json f = {{"name", spec.name},
                      {"cases", spec.cases.size()},
                      {"perCase", harnessDrawsPerCase(spec)}};
            json uniforms = json::array();
            for (const FunctionCase& c : spec.cases) uniforms.push_back(c.uniforms);
            f["uniforms"] = uniforms;
            try {
                const HarnessProgram p = assembleHarness(spec, *stage_, sources_, {}, true);
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
            const FunctionSpec& f = spec(name);
            return outcomeJson(scoreFunctionResults(f, harnessResults(floats), wantsOf(f))).dump();
        } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
    }

private:
    const FunctionSpec& spec(const std::string& name) const {
        for (const FunctionSpec& s : specs_)
            if (s.name == name) return s;
        throw Error("stage " + (stage_ ? stage_->id : std::string("?")) +
                    " has no function check '" + name + "'");
    }
    const StageInfo* stage_ = nullptr;
    StageSources sources_;
    std::vector<FunctionSpec> specs_;  // with their harness GLSL from the tables
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
        CheckView view;  // any view: only its name and "why" go into the verdict
        const ViewOutcome v = judgeView(stage, view, imageFrom(mine, width, height),
                                        imageFrom(expected, width, height),
                                        c.value("nonFinite", 0L), c.value("todoPixels", 0L));
        return json{{"passed", v.passed},
                    {"badShare", v.diff.badShare},
                    {"maxDiff", v.diff.maxDiff},
                    {"sameSize", v.diff.sameSize},
                    {"description", describe(v.diff)},
                    {"hint", v.hint}}
            .dump();
    } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
}

// A picture as the page reads it back from a check's float target (RGBA
// floats, rows bottom-up) with its TODO marks (one byte per pixel, the
// same rows; may be empty): top-down RGBA bytes converted as natively
// (imageFromFloats), the NaN/Inf pixels and the marked ones counted.
// Answers {rgba: Uint8Array, nonFinite, todoPixels}.
val viewImage(const val& floats, const val& marks, int width, int height) {
    const std::vector<float> bottomUp = emscripten::convertJSArrayToNumberVector<float>(floats);
    const std::size_t row = std::size_t(width) * 4;
    if (bottomUp.size() != row * std::size_t(height)) {
        val error = val::object();
        error.set("error", "viewImage: " + std::to_string(bottomUp.size()) + " floats for " +
                               std::to_string(width) + "x" + std::to_string(height));
        return error;
    }
    std::vector<float> rows(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row), row,
                    rows.begin() + std::ptrdiff_t(std::size_t(y) * row));
    long nonFinite = 0;
    const Image image = imageFromFloats(rows, width, height, &nonFinite);
    long todoPixels = 0;
    for (std::uint8_t m : emscripten::convertJSArrayToNumberVector<std::uint8_t>(marks))
        todoPixels += m > 127;
    val out = val::object();
    out.set("rgba", typedArray("Uint8Array", image.rgba));
    out.set("nonFinite", double(nonFinite));
    out.set("todoPixels", double(todoPixels));
    return out;
}

// One `raylab check` in the page: the page runs the harnesses and draws the
// views; this judges each result as natively and writes the report in
// native's words (check_report.h).
class CheckSession {
public:
    // HEADER: the report's first line ("raylab check: stage ..."); TODOSJSON:
    // the lab's open TODOs [{file, line, title}].
    CheckSession(const std::string& stage, const std::string& header, const std::string& todosJson)
        : header_(header) {
        try {
            stage_ = &findStage(stage);
            for (const json& t : json::parse(todosJson))
                todos_.push_back({t.at("file"), t.at("line"), t.at("title")});
        } catch (const std::exception& e) { error_ = e.what(); }
    }
    std::string error() const { return error_; }

    // What a harness wrote for function NAME; answers the outcome as JSON.
    std::string addFunction(const std::string& name, const val& floats) {
        try {
            return scoreInto(name, floats);
        } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
    }
    // A harness that did not build: MESSAGE says why (mapped to file:line).
    std::string addFunctionNotBuilt(const std::string& name, const std::string& message) {
        try {
            FunctionOutcome f;
            f.name = name;
            f.total = int(functionSpec(name).cases.size());
            f.compiled = false;
            f.firstFailure = "does not compile: " + message;
            return record(f);
        } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
    }

    // View VIEWNAME: the student's picture and the reference (top-down RGBA
    // bytes, WIDTH x HEIGHT). Answers {passed, description, hint}.
    std::string addView(const std::string& viewName, const val& mine, const val& expected,
                        int width, int height, double nonFinite, double todoPixels) {
        try {
            return judgeInto(viewName, mine, expected, width, height, nonFinite, todoPixels);
        } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
    }

    // Count check NAME, per check view: RESULTSJSON [{view, applies, passed,
    // detail}] (the page counted; the core judged each, as natively).
    std::string addCount(const std::string& name, const std::string& resultsJson) {
        try {
            CountOutcome c;
            c.name = name;
            for (const json& r : json::parse(resultsJson))
                if (r.value("applies", false))
                    tallyCount(c, r.value("view", ""), r.value("passed", false),
                               r.value("detail", ""));
            counts_.push_back(c);
            return json{{"passed", countPassed(c)}}.dump();
        } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
    }

    // A count check the page cannot run, and why.
    void addCountNotRun(const std::string& name, const std::string& why) {
        notRun_.push_back("  ---- " + name + ": not checked here: " + why + "\n");
        countsNotRun_.push_back(name);
    }

    // No score line in the report (a test that compares verdicts only).
    void noScore() { scored_ = false; }

    // View VIEWNAME drawn by the lab as handed out (top-down RGBA bytes), for
    // the score's rule on views that lab draws (stage_score.h); the page
    // draws them when a view fails, as native's check does.
    std::string addUntouched(const std::string& viewName, const val& rgba, int width, int height) {
        try {
            untouched_[viewName] = imageFrom(rgba, width, height);
            return "{}";
        } catch (const std::exception& e) { return json{{"error", e.what()}}.dump(); }
    }

    int passed() const { return count(true); }
    int failed() const { return count(false); }
    // The report as `raylab check` prints it: the TODOs, the header, the
    // function checks, the views, the count checks, the summary.
    std::string report() const {
        std::string out = formatOpenTodos(todos_) + header_ + "\n";
        std::vector<std::string> failedFunctions;
        std::vector<FunctionSpec> failedSpecs;  // with their harness GLSL, from the tables
        if (!functions_.empty()) out += formatFunctionsHeading();
        for (const FunctionOutcome& f : functions_) {
            out += formatFunctionLine(f, !failedFunctions.empty());
            if (f.passed == f.total) continue;
            const FunctionSpec spec =
                withHarnessFrom(tablesAsData(), functionSpec(f.name), kTablesAsData);
            std::vector<const FunctionSpec*> above;
            for (const FunctionSpec& s : failedSpecs) above.push_back(&s);
            out += formatReadsFailedNote(spec, above);
            failedFunctions.push_back(f.name);
            failedSpecs.push_back(spec);
        }
        out += formatViewsHeading();
        for (const ViewOutcome& v : views_)
            out += formatViewLines(v, failedFunctions, todos_.size());
        for (const CountOutcome& c : counts_) out += formatCountLine(c);
        for (const std::string& line : notRun_) out += line;
        return out + formatSummary(passed(), failed()) + scoreLine();
    }

private:
    // The score the grader gives for these checks (native: cmd_check.cpp),
    // or why the page gives none (a count check it cannot run).
    std::string scoreLine() const {
        if (!scored_) return "";
        if (!countsNotRun_.empty())
            return "  score: given natively only (" + countsNotRun_.front() +
                   " is not checked here; raylab check prints the score)\n";
        std::vector<std::string> viewWeights, otherNames;
        for (const ViewOutcome& v : views_) viewWeights.push_back(v.name);
        for (const FunctionOutcome& f : functions_) otherNames.push_back(f.name);
        for (const CountOutcome& c : counts_) otherNames.push_back(c.name);
        const std::vector<double> points = checkPoints(stage_->grading, viewWeights, otherNames);
        std::vector<CheckCredit> credits;
        for (std::size_t i = 0; i < views_.size(); ++i) {
            const ViewOutcome& v = views_[i];
            CheckCredit c{true, points[i], v.diff.badShare, v.nonFinite > 0};
            auto it = untouched_.find(v.name);
            if (it != untouched_.end())
                creditHandedOutView(c, v.passed, mine_[i], expected_[i], it->second);
            credits.push_back(c);
        }
        for (const FunctionOutcome& f : functions_)
            credits.push_back({false, points[credits.size()], wrongShare(f.passed, f.total)});
        for (const CountOutcome& c : counts_)
            credits.push_back({false, points[credits.size()], wrongShare(c.passed, c.total)});
        return formatScoreLine(scoreChecks(credits), stage_->grading.seededViews);
    }
    std::string scoreInto(const std::string& name, const val& floats) {
        const FunctionSpec& s = functionSpec(name);
        return record(scoreFunctionResults(s, harnessResults(floats), wantsOf(s)));
    }
    std::string judgeInto(const std::string& viewName, const val& mine, const val& expected,
                          int width, int height, double nonFinite, double todoPixels) {
        const CheckView* view = nullptr;
        for (const CheckView& v : stage_->checkViews)
            if (v.name == viewName) view = &v;
        if (!view) throw Error("stage " + stage_->id + " has no check view '" + viewName + "'");
        // As natively, the function checks ran first: a failing one is the evidence.
        bool functionFailed = false;
        for (const FunctionOutcome& f : functions_) functionFailed |= f.passed != f.total;
        mine_.push_back(imageFrom(mine, width, height));
        expected_.push_back(imageFrom(expected, width, height));
        views_.push_back(judgeView(*stage_, *view, mine_.back(), expected_.back(), long(nonFinite),
                                   long(todoPixels), functionFailed));
        const ViewOutcome& v = views_.back();
        return json{{"passed", v.passed}, {"description", describe(v.diff)}, {"hint", v.hint}}
            .dump();
    }
    std::string record(const FunctionOutcome& f) {
        functions_.push_back(f);
        return outcomeJson(f).dump();
    }
    int count(bool ok) const {
        int n = 0;
        for (const FunctionOutcome& f : functions_) n += (f.passed == f.total) == ok;
        for (const ViewOutcome& v : views_) n += v.passed == ok;
        for (const CountOutcome& c : counts_) n += countPassed(c) == ok;
        return n;
    }
    const StageInfo* stage_ = nullptr;
    std::string header_, error_;
    std::vector<OpenTodo> todos_;
    std::vector<FunctionOutcome> functions_;
    std::vector<ViewOutcome> views_;
    std::vector<CountOutcome> counts_;
    std::vector<Image> mine_, expected_;  // views_'s pictures, for the score
    std::map<std::string, Image> untouched_;
    std::vector<std::string> notRun_, countsNotRun_;
    bool scored_ = true;
};

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
    emscripten::function("viewImage", &raylab::viewImage);
    using raylab::CheckSession;
    emscripten::class_<CheckSession>("CheckSession")
        .constructor<std::string, std::string, std::string>()
        .function("error", &CheckSession::error)
        .function("addFunction", &CheckSession::addFunction)
        .function("addFunctionNotBuilt", &CheckSession::addFunctionNotBuilt)
        .function("addView", &CheckSession::addView)
        .function("addCount", &CheckSession::addCount)
        .function("addCountNotRun", &CheckSession::addCountNotRun)
        .function("addUntouched", &CheckSession::addUntouched)
        .function("noScore", &CheckSession::noScore)
        .function("passed", &CheckSession::passed)
        .function("failed", &CheckSession::failed)
        .function("report", &CheckSession::report);
    using raylab::FunctionChecks;
    emscripten::class_<FunctionChecks>("FunctionChecks")
        .constructor<std::string>()
        .function("error", &FunctionChecks::error)
        .function("list", &FunctionChecks::list)
        .function("texels", &FunctionChecks::texels)
        .function("score", &FunctionChecks::score);
}
