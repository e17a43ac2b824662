#pragma once
// The views a stage is graded from: its check views (the ones students run
// with `raylab check`) plus a few drawn from a seed the instructor can keep
// secret, so that a submission cannot be tuned to a fixed set of images.
#include "stage_catalog.h"
#include "stage_grading.h"

#include <vector>

namespace raylab {

// Same seed, same views, on every machine (no std:: distributions, whose
// results differ between standard libraries).
// COUNT seeded views (StageGrading::seededViews) follow the check views; the
// first N of any count are the same views.
std::vector<CheckView> gradingViews(const StageInfo& stage, unsigned seed,
                                    int count = kSeededViewsPerStage);

}  // namespace raylab
