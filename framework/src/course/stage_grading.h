#pragma once
// How a stage's 100 points are shared among its checks, and how a check's
// credit falls with what it measured. The numbers are data: stage.json's
// "grading" holds the stage's defaults (chosen against the mistakes
// catalogue: docs/grading.md), and a course file may override them
// (course_file.h), so an instructor changes weights without touching C++.
//
//   "grading": {"views": 50, "weights": {"far-from-origin": 2, "lightVisible": 1}}
//
//  - views: the points of the image checks (the check views and the seeded
//    views); the rest of the 100 go to the function and count checks. A
//    stage with neither gives the views all 100.
//  - weights: a check's weight within its share (default 1; 0 leaves it
//    out of the score). A seeded view weighs as much as the view it varies.
//  - seeded_views: how many views grading adds, drawn from the seed (0 to
//    3, default 3). With 0 a stage is graded from exactly the checks
//    `raylab check` runs, and the score it prints is the grade.
#include <map>
#include <string>
#include <vector>

namespace raylab {

struct StageInfo;

// Grading adds this many views drawn from the instructor's seed, each a small
// move of a check view (grading/grade_views.h).
inline constexpr int kSeededViewsPerStage = 3;

struct StageGrading {
    double viewPoints = 70.0;
    int seededViews = kSeededViewsPerStage;
    std::map<std::string, double> weights;
    double weight(const std::string& check) const;
};

// The credit (0..1) of a view whose share BADSHARE of pixels differ: 1 up to
// the tolerance of `raylab check` (0.5%), then falling with the logarithm of
// the share to 0 where the picture is clearly wrong (10%): no cliff.
double viewCredit(double badShare);
// The credit of a function or count check with this share of wrong cases
// (or views): falling linearly from 1 (none) to 0 (a quarter or more).
double caseCredit(double wrongShare);
inline constexpr double kViewZeroShare = 0.10;
inline constexpr double kCaseZeroShare = 0.25;

// The points of each check of STAGE under GRADING: VIEWS are the grading
// views' weight names (a seeded view's base view), OTHERS the function and
// count checks' names. Returns the points in the same order, views first.
std::vector<double> checkPoints(const StageGrading& grading, const std::vector<std::string>& views,
                                const std::vector<std::string>& others);

// Checks GRADING against STAGE: weights only for the stage's checks, views
// in 0..100, no share whose weights add up to zero. Throws Error("WHERE:
// why") naming WHERE (the file and key that set it).
void validateGrading(const StageGrading& grading, const StageInfo& stage, const std::string& where);

// "How you are graded" of a stage's guide, from its effective grading.
std::string gradingGuideSection(const StageInfo& stage, const StageGrading& grading);

// GUIDE with the text between its "<!-- grading: ... -->" and "<!-- /grading
// -->" lines replaced by gradingGuideSection (the markers stay, so that
// raylab-labgen can write it again); GUIDE itself when it has no markers.
// Throws Error when the closing marker is missing.
// COURSERULES (a course's deadline, late policy, earlier stages:
// course_file.h's courseRulesSection) follows the section when not empty.
std::string withGradingSection(const std::string& guide, const StageInfo& stage,
                               const StageGrading& grading, const std::string& courseRules = "");

}  // namespace raylab
