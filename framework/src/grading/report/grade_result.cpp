#include "grade_result.h"

namespace raylab {

double StudentResult::score() const {
    double total = 0;
    for (const StageResult& s : stages)
        if (!s.excused) total += s.score;
    return total;
}

double StudentResult::maxScore() const {
    double total = 0;
    for (const StageResult& s : stages)
        if (!s.excused) total += s.maxScore;
    return total;
}

}  // namespace raylab
