#include "stage_score.h"

#include <cmath>
#include <cstdio>

namespace raylab {

StageScore scoreChecks(std::vector<CheckCredit>& checks) {
    double earned = 0, possible = 0;
    for (CheckCredit& c : checks) {
        const double credit = c.image ? viewCredit(c.measured) : caseCredit(c.measured);
        c.score = c.earnsNothing ? 0.0 : c.points * credit;
        if (c.image && c.reaches) {
            earned += c.score;
            possible += c.points;
        }
    }
    StageScore s;
    s.reachShare = possible > 0 ? earned / possible : 1.0;
    for (CheckCredit& c : checks) {
        if (c.image && !c.reaches && s.reachShare < 1.0) c.score *= s.reachShare;
        s.total += c.score;
    }
    s.total = std::round(s.total * 100.0) / 100.0;
    return s;
}

double wrongShare(int passed, int total) {
    return total > 0 ? 1.0 - double(passed) / double(total) : 1.0;
}

void creditHandedOutView(CheckCredit& c, bool passed, const Image& mine, const Image& expected,
                         const Image& handedOut) {
    const CompareTolerance tolerance;
    auto agree = [&](const Image& a, const Image& b) {
        return imagesAgree(compareImages(a, b, tolerance.channel), tolerance);
    };
    c.reaches = !agree(handedOut, expected);
    c.earnsNothing = c.earnsNothing || (!passed && agree(mine, handedOut));
}

std::string formatScoreLine(const StageScore& score, int seeded) {
    char line[320];
    if (seeded > 0)
        std::snprintf(line, sizeof line,
                      "  score: %.2f/100 for these checks, by the grader's rule; the grader "
                      "also draws %d views close to these\n"
                      "  from a seed (each weighs as the view it varies), so make the stage "
                      "right everywhere\n",
                      score.total, seeded);
    else
        std::snprintf(line, sizeof line,
                      "  score: %.2f/100, by the grader's rule (your course grades exactly "
                      "these checks)\n",
                      score.total);
    return line;
}

}  // namespace raylab
