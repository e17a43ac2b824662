#pragma once
// The roster an instructor gives `raylab grade --roster FILE`: a CSV whose
// header names the columns. `student` (the submission folder's name) is
// required; `id` (the student's id, Canvas's "SIS User ID"), `name`
// (as the LMS shows it), `canvas_id` (Canvas's own user id), `login_id`
// (Canvas's "SIS Login ID"; the username Moodle, Blackboard and Brightspace
// match), `section` (a report per section, class_sections.h) and `email`
// (Moodle can match by it) are optional. summary.csv takes the id from it,
// `--lms` what each LMS matches by; a student in the roster without a folder
// is listed as not submitted.
#include "grade_result.h"

#include <filesystem>
#include <map>
#include <string>

namespace raylab {

// Folder name -> entry. Throws Error("FILE: line N: why").
std::map<std::string, RosterEntry> readRoster(const std::filesystem::path& file);

}  // namespace raylab
