#pragma once
// `raylab grade --lms canvas,moodle,blackboard,brightspace`: each LMS's
// gradebook import (grade_report.h) as OUT/<lms>.csv, from the roster's ids
// and the course file's column ids (course_file.h, "lms").
#include "course_file.h"
#include "grade_result.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace raylab {

// The LMSs an export is written for, and the file each is written to.
inline const std::vector<std::string> kLmsNames = {"canvas", "moodle", "blackboard", "brightspace"};

// "canvas,moodle" -> {"canvas", "moodle"}; "" -> {}. Throws Error naming an
// unknown LMS.
std::vector<std::string> parseLmsList(const std::string& list);

// Throws Error("--lms NAME: ...") when no roster entry has an id that LMS
// matches by: said before any grading, not after it.
void checkRosterServes(const std::vector<std::string>& lmss,
                       const std::map<std::string, RosterEntry>& roster);

// Writes OUT/<lms>.csv for each of LMSS and says how to import it; removes
// the other LMSs' files of an earlier run.
void writeLmsExports(const ClassResult& result, const std::vector<std::string>& lmss,
                     const LmsColumns& columns, const std::filesystem::path& outDir);

}  // namespace raylab
