#pragma once
// `raylab grade`'s work from its options to its reports: the course's
// options checked before any work; the class graded (grade_class.h); then a
// share's results for --merge (grade_shards.h), or a regrade of one student
// (--only) put into the earlier run's results (class_file.h), and the
// reports (class_reports.h).
#include "grade_options.h"

#include <optional>

namespace raylab {

// The wall time of this run in seconds; nullopt when it was interrupted
// (Ctrl-C: no report written). Throws Error on bad options, before any work.
std::optional<double> gradeAndReport(const GradeOptions& options);

}  // namespace raylab
