#include "stage_grading.h"

#include "error.h"
#include "image_compare.h"
#include "stage_catalog.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace raylab {

double StageGrading::weight(const std::string& check) const {
    auto it = weights.find(check);
    return it == weights.end() ? 1.0 : it->second;
}

double viewCredit(double badShare) {
    const double pass = CompareTolerance{}.maxBadShare;
    if (!(badShare > pass)) return 1.0;
    if (badShare >= kViewZeroShare) return 0.0;
    return 1.0 - std::log(badShare / pass) / std::log(kViewZeroShare / pass);
}

double caseCredit(double wrongShare) {
    if (!(wrongShare > 0.0)) return 1.0;
    return std::max(0.0, 1.0 - wrongShare / kCaseZeroShare);
}

std::vector<double> checkPoints(const StageGrading& g, const std::vector<std::string>& views,
                                const std::vector<std::string>& others) {
    const double viewShare = others.empty() ? 100.0 : g.viewPoints;
    double viewWeights = 0, otherWeights = 0;
    for (const std::string& v : views) viewWeights += g.weight(v);
    for (const std::string& o : others) otherWeights += g.weight(o);
    std::vector<double> points;
    for (const std::string& v : views)
        points.push_back(viewWeights > 0 ? viewShare * g.weight(v) / viewWeights : 0.0);
    for (const std::string& o : others)
        points.push_back(otherWeights > 0 ? (100.0 - viewShare) * g.weight(o) / otherWeights : 0.0);
    return points;
}

void validateGrading(const StageGrading& g, const StageInfo& stage, const std::string& where) {
    if (!(g.viewPoints >= 0.0 && g.viewPoints <= 100.0))
        throw Error(where + ".views: expected points from 0 to 100");
    std::set<std::string> known;
    double views = 0, others = 0;
    for (const CheckView& v : stage.checkViews) {
        known.insert(v.name);
        views += g.weight(v.name);
    }
    for (const std::string& f : stage.functionChecks) {
        known.insert(f);
        others += g.weight(f);
    }
    for (const std::string& c : stage.countChecks) {
        known.insert(c);
        others += g.weight(c);
    }
    for (const auto& [name, w] : g.weights) {
        if (!known.count(name)) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            throw Error(where + ".weights." + name + ": not a check of " + stage.id +
                        " (its checks: " + list + ")");
        }
        if (!(w >= 0.0 && w <= 1000.0))
            throw Error(where + ".weights." + name + ": expected a weight from 0 to 1000");
    }
    const bool hasOthers = !stage.functionChecks.empty() || !stage.countChecks.empty();
    if (!(views > 0.0) && (!hasOthers || g.viewPoints > 0.0))
        throw Error(where + ".weights: the views' weights add up to 0");
    if (hasOthers && !(others > 0.0) && g.viewPoints < 100.0)
        throw Error(where + ".weights: the function and count checks' weights add up to 0");
}

namespace {

// Points to three significant digits ("5.56", "50"); weights as given ("0.5").
std::string printed(const char* format, double value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}
std::string points(double p) { return printed("%.3g", p); }
std::string weightText(double w) { return printed("%g", w); }

}  // namespace

std::string gradingGuideSection(const StageInfo& stage, const StageGrading& g) {
    const std::size_t nViews = stage.checkViews.size();
    const std::size_t nOthers = stage.functionChecks.size() + stage.countChecks.size();
    const double viewShare = nOthers == 0 ? 100.0 : g.viewPoints;
    // Seeded views count as an average view here: which views they vary
    // depends on the seed.
    double total = 0;
    for (const CheckView& v : stage.checkViews) total += g.weight(v.name);
    const double average = total / double(nViews);
    const double perWeight = viewShare / (total + g.seededViews * average);

    std::string t;
    if (g.seededViews > 0)
        t += "Your instructor grades with `raylab grade`, which checks this stage from the\n" +
             std::to_string(nViews) + " views of `raylab check` plus " +
             std::to_string(g.seededViews) +
             " more views close to them, drawn from a\nseed the instructor keeps secret: make "
             "the stage right everywhere, not only\nin the listed views. The stage is worth 100 "
             "points:\n\n";
    else
        t += "Your instructor grades with `raylab grade`, which checks this stage from the\n" +
             std::to_string(nViews) +
             " views of `raylab check` and nothing more: the score `raylab check` prints\n"
             "is your grade. The stage is worth 100 points:\n\n";
    t += "* **Images, " + points(viewShare) +
         " points**, shared by the views by weight (a view drawn from\n  the seed weighs as "
         "much as the view it varies; one unit of weight is worth\n  about " +
         points(perWeight) + " points):\n\n";
    t += "  | view | weight | what it checks |\n  | --- | --- | --- |\n";
    for (const CheckView& v : stage.checkViews)
        t += "  | `" + v.name + "` | " + weightText(g.weight(v.name)) + " | " + v.why + " |\n";
    auto percent = [](double credit) { return std::to_string(int(std::lround(100.0 * credit))); };
    t += "\n  A view earns all of its points when at most 0.5% of its pixels differ from\n"
         "  the solution's (the rule of `raylab check`), and less the more differ, with\n"
         "  no jump: 1% of pixels earns " +
         percent(viewCredit(0.01)) + "%, 2% earns " + percent(viewCredit(0.02)) + "%, 5% earns " +
         percent(viewCredit(0.05)) + "%, " + percent(kViewZeroShare) +
         "% or more\n  nothing. A picture still equal to the lab as handed out earns nothing; a\n"
         "  view the handed-out lab already draws right (one with this stage's feature\n"
         "  switched off) earns only the share the other views earned, so an untouched\n"
         "  lab scores 0; a view with NaN or Inf pixels earns nothing.\n";
    if (nOthers > 0) {
        t += "* **Functions" + std::string(stage.countChecks.empty() ? "" : " and counts") + ", " +
             points(100.0 - viewShare) + " points**";
        double others = 0;
        for (const std::string& f : stage.functionChecks) others += g.weight(f);
        for (const std::string& c : stage.countChecks) others += g.weight(c);
        std::string list;
        auto add = [&](const std::string& name) {
            const double p = others > 0 ? (100.0 - viewShare) * g.weight(name) / others : 0.0;
            list += (list.empty() ? "" : ", ") + ("`" + name + "` " + points(p));
        };
        for (const std::string& f : stage.functionChecks) add(f);
        for (const std::string& c : stage.countChecks) add(c);
        t += ": " + list + ".";
        if (!stage.functionChecks.empty())
            t += " A function\n  runs on a table of inputs (the hard cases included) against a\n"
                 "  double-precision version; `raylab check` runs the same tables and prints\n"
                 "  the first case that fails.";
        if (!stage.countChecks.empty())
            t += " A count check compares a number your\n  shaders produce with the same "
                 "number worked out on the CPU, in every graded view\n  that draws it.";
        const std::string unit = stage.functionChecks.empty() ? "view" : "case";
        t += " Each earns all of its points when every " + unit +
             " agrees,\n  and less with every one that does not: 5% of them wrong earns " +
             percent(caseCredit(0.05)) + "%, 10%\n  earns " + percent(caseCredit(0.10)) + "%, " +
             percent(kCaseZeroShare) + "% or more nothing.\n";
    }
    t += "\nA stage that does not compile, runs past the time limit or crashes earns 0\n"
         "points, and the report says why (for a compiler error: your file and line).\n";
    return t;
}

std::string withGradingSection(const std::string& guide, const StageInfo& stage,
                               const StageGrading& grading, const std::string& courseRules) {
    const std::string open = "<!-- grading:", close = "<!-- /grading -->";
    const std::size_t at = guide.find(open);
    if (at == std::string::npos) return guide;
    const std::size_t bodyStart = guide.find('\n', at);
    const std::size_t end = guide.find(close, at);
    if (bodyStart == std::string::npos || end == std::string::npos || end < bodyStart)
        throw Error(stage.id + "/README.md: " + open + " without " + close);
    return guide.substr(0, bodyStart + 1) + gradingGuideSection(stage, grading) +
           (courseRules.empty() ? "" : "\n" + courseRules) + guide.substr(end);
}

}  // namespace raylab
