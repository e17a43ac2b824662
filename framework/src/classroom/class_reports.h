#pragma once
// The class's reports, after the course's workflow: the late policy (with
// the submission times), the roster, the catalogued mistakes the failures
// repeat; then <student>/results.json, summary.csv, junit.xml, report.html
// (with --lms an <lms>.csv each, with sections sections/) in OUT and the
// summary table on stdout. A whole run, a --merge of shares and a --only
// regrade all finish here, so they finish the same way.
#include "grade_options.h"
#include "grade_result.h"

#include <filesystem>

namespace raylab {

void finishAndReport(ClassResult result, const GradeOptions& options,
                     const std::filesystem::path& outDir);

}  // namespace raylab
