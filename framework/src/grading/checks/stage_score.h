#pragma once
// A stage's score from its checks' verdicts: one rule for `raylab grade`
// (grade_stage.cpp), `raylab check` and the page's Check, so that the score a
// student sees before submitting is the one the grader gives for the same
// checks. The points of each check come from stage_grading.h (checkPoints);
// a check's credit falls continuously with what it measured (viewCredit,
// caseCredit).
#include "image_compare.h"
#include "stage_grading.h"

#include <string>
#include <vector>

namespace raylab {

struct CheckCredit {
    bool image = true;    // an image check (viewCredit) or a function/count check (caseCredit)
    double points = 0;    // its points of the stage's 100
    double measured = 0;  // the share of pixels that differ, or of cases (views) wrong
    // NaN or Inf pixels, or still the picture of the lab as handed out: no credit.
    bool earnsNothing = false;
    // An image check whose view the lab as handed out draws wrong: it reaches
    // the stage's code. A view that does not earns at most the share of their
    // points the reaching views earned, so that an untouched lab scores 0.
    bool reaches = true;
    double score = 0;  // out
};

struct StageScore {
    double total = 0;       // rounded to 0.01, as grading reports it
    double reachShare = 1;  // the share the reaching views earned (1: no view scaled)
};

// Fills each check's score and returns the stage's total.
StageScore scoreChecks(std::vector<CheckCredit>& checks);

// The share of a function check's cases (or a count check's views) that are
// wrong: what caseCredit reads. None counted is all wrong.
double wrongShare(int passed, int total);

// An image check against the lab as handed out's picture of the same view
// (HANDEDOUT): it reaches the stage's code when that picture is wrong, and a
// failing MINE equal to it earns nothing. EXPECTED: the reference picture.
void creditHandedOutView(CheckCredit& c, bool passed, const Image& mine, const Image& expected,
                         const Image& handedOut);

// "score 87.35/100 by the grader's rule for these checks; ..." for `raylab
// check`: SEEDED is the number of views the grader adds (StageGrading::
// seededViews), said so that the student knows what else counts.
std::string formatScoreLine(const StageScore& score, int seeded);

}  // namespace raylab
