#include "check_report.h"

#include <cstdio>
#include <set>

namespace raylab {

namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args) {
    const int n = std::snprintf(nullptr, 0, pattern, args...);
    std::string out(std::size_t(n) + 1, '\0');
    std::snprintf(out.data(), out.size(), pattern, args...);
    out.pop_back();
    return out;
}

}  // namespace

ViewOutcome judgeView(const StageInfo& stage, const CheckView& view, const Image& mine,
                      const Image& expected, long nonFinite, long todoPixels, bool functionFailed) {
    const CompareTolerance tolerance;
    ViewOutcome v;
    v.name = view.name;
    v.why = view.why;
    v.nonFinite = nonFinite;
    v.diff = compareImages(mine, expected, tolerance.channel);
    v.passed = imagesAgree(v.diff, tolerance) && nonFinite == 0;
    if (v.passed) return v;
    // A failing function check is the evidence: its line (and its hint, where
    // the failing cases prove a cause) says more than the picture's
    // brightness, so the stage's usual causes are not guessed then.
    if (functionFailed) {
        v.hint = diagnose(mine, expected, tolerance.channel, {"", "", todoPixels, nonFinite});
        return v;
    }
    v.hint = diagnose(mine, expected, tolerance.channel,
                      {stage.hintDarker, stage.hintBrighter, todoPixels, nonFinite});
    // The view's own cause: what only this view's picture shows.
    if (!view.hint.empty() && nonFinite == 0 && todoPixels == 0)
        v.hint += (v.hint.empty() ? "" : "; ") + view.hint;
    return v;
}

std::string formatOpenTodos(const std::vector<OpenTodo>& todos) {
    if (todos.empty()) return "";
    std::string out = format("raylab: %zu open TODO%s in this lab (in colour frames their pixels "
                             "show magenta stripes):\n",
                             todos.size(), todos.size() == 1 ? "" : "s");
    for (const OpenTodo& t : todos)
        out += "  " + t.file + ":" + std::to_string(t.line) + ": " + t.title + "\n";
    return out;
}

std::string formatFunctionsHeading() {
    return "  function checks: each function on a table of inputs (hard cases included) "
           "against double precision\n";
}

std::string formatFunctionLine(const FunctionOutcome& f, bool earlierFailed) {
    const bool ok = f.passed == f.total;
    return format("  %s %-18s %d/%d cases%s%s\n", ok ? "PASS" : "FAIL", f.name.c_str(), f.passed,
                  f.total, ok ? "" : "; first failure: ", f.firstFailure.c_str()) +
           (f.cause.empty() || earlierFailed ? "" : "       hint: " + f.cause + "\n");
}

namespace {

// The files SPEC's harness includes by name: its includes and the #include
// lines of its prelude and helpers.
std::set<std::string> harnessFiles(const FunctionSpec& spec) {
    std::set<std::string> files(spec.includes.begin(), spec.includes.end());
    for (const std::string* glsl : {&spec.prelude, &spec.helpers})
        for (std::size_t at = glsl->find("#include \""); at != std::string::npos;
             at = glsl->find("#include \"", at + 1)) {
            const std::size_t from = at + 10, to = glsl->find('"', from);
            if (to != std::string::npos) files.insert(glsl->substr(from, to - from));
        }
    return files;
}

}  // namespace

std::string formatReadsFailedNote(const FunctionSpec& spec,
                                  const std::vector<const FunctionSpec*>& failedAbove) {
    const std::set<std::string> reads = harnessFiles(spec);
    const std::string own = spec.includes.empty() ? "" : spec.includes.back();
    for (const FunctionSpec* earlier : failedAbove) {
        if (earlier->includes.empty()) continue;
        const std::string& file = earlier->includes.back();  // where the earlier function lives
        if (file != own && reads.count(file))
            return "       note: this check also runs your " + file + ", where " + earlier->name +
                   " failed above: fix that first, then check again\n";
    }
    return "";
}

std::string formatViewsHeading() {
    const CompareTolerance tolerance;
    return format("  a view passes when at most %.1f%% of its pixels differ by more than %d/255 "
                  "from every pixel of the\n"
                  "  reference's 3x3 neighbourhood\n",
                  tolerance.maxBadShare * 100.0, tolerance.channel);
}

std::string formatViewLines(const ViewOutcome& v, const std::vector<std::string>& failedFunctions,
                            std::size_t openTodos) {
    std::string out = format(
        "  %s %-14s %s%s\n", v.passed ? "PASS" : "FAIL", v.name.c_str(), describe(v.diff).c_str(),
        v.nonFinite
            ? ("; " + std::to_string(v.nonFinite) + " pixels are NaN or Inf (shown magenta)")
                  .c_str()
            : "");
    if (v.passed) return out;
    out += "       this view checks: " + v.why + "\n";
    if (!v.hint.empty()) out += "       hint: " + v.hint + "\n";
    if (!failedFunctions.empty())
        out += "       note: the function check " + failedFunctions.front() +
               " failed above, with its first wrong input\n";
    // A fact, not a guess: unfinished stubs change the picture.
    if (openTodos > 0 && v.hint.find("unfinished TODO") == std::string::npos)
        out += format("       note: %zu TODO%s of this lab %s still open (listed above)\n",
                      openTodos, openTodos == 1 ? "" : "s", openTodos == 1 ? "is" : "are");
    return out;
}

std::vector<std::string> causesNamed(const std::string& report, const StageInfo& stage) {
    std::set<std::string> named;
    auto look = [&](const std::string& text, const std::string& id) {
        if (!text.empty() && report.find(text) != std::string::npos) named.insert(id);
    };
    look(stage.hintDarker, "darker");
    look(stage.hintBrighter, "brighter");
    for (const CheckView& v : stage.checkViews) look(v.hint, "view:" + v.name);
    for (const FunctionSpec* f : functionSpecsFor(stage))
        for (const FunctionDiagnosis& d : f->diagnoses) look(d.cause, f->name + ":" + d.id);
    return {named.begin(), named.end()};
}

bool countPassed(const CountOutcome& c) { return c.total > 0 && c.passed == c.total; }

std::string formatCountLine(const CountOutcome& c) {
    const bool ok = countPassed(c);
    return format("  %s %-18s %d/%d views%s%s\n", ok ? "PASS" : "FAIL", c.name.c_str(), c.passed,
                  c.total,
                  ok ? "; " : "; first failure: ", (ok ? c.example : c.firstFailure).c_str());
}

std::string formatSummary(int passed, int failed) {
    return format("%d passed, %d failed\n", passed, failed);
}

void tallyCount(CountOutcome& c, const std::string& view, bool passed, const std::string& detail) {
    ++c.total;
    if (c.example.empty()) c.example = "view " + view + ": " + detail;
    if (passed) ++c.passed;
    else if (c.firstFailure.empty()) c.firstFailure = "view " + view + ": " + detail;
}

}  // namespace raylab
