#pragma once
// PrairieLearn's results.json for one graded upload (`raylab prairielearn`,
// examples/prairielearn/): the score from 0 to 1, whether the upload was
// gradable (an upload that is not costs the student no attempt), one test per
// check with its points and message, and the difference heat maps of failed
// views as images, within PrairieLearn's 1 MB for the whole file.
#include "upload_grading.h"

#include <nlohmann/json.hpp>

namespace raylab {

// HIDESEEDED: PrairieLearn shows every test at once (its tests have no
// visibility of their own, unlike Gradescope's), so the seeded views are one
// test whose points count but whose views, messages and pictures are not
// shown; false lists each (a regrade after the due date).
nlohmann::ordered_json prairieLearnResults(const UploadGrade& graded, bool hideSeeded);

}  // namespace raylab
