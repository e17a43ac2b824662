#pragma once
// What `raylab grade` does with a graded class before it writes the reports:
// the course's late policy, the roster, the class summary's catalogued
// mistakes. Each step works on the ClassResult only, so a
// --merge of shares and a --only regrade finish the class the same way.
#include "course_file.h"
#include "grade_result.h"
#include "submission_times.h"

#include <map>
#include <string>
#include <vector>

namespace raylab {

// The course file's rules for each student's stages: an excused stage
// counts for nothing (StageResult::excused); a late one loses the late
// policy's share of its score (latePenalty, lateNote), its deadline moved by
// the student's extension. TIMES (null: no late policy to apply) says when
// each submitted. NAMEOF maps a result's name back to the folder the course
// file and the times know (the same unless the names are pseudonyms).
// Stages not submitted or without a deadline are never late; a graded stage
// without a time is noted and taken as on time.
void applyCourseRules(ClassResult& result, const CourseSettings& course,
                      const SubmissionTimes* times,
                      const std::map<std::string, std::string>& folderOf);

// Every student's roster entry; roster students without a folder are added
// as not submitted. Returns the folders the roster does not list. ROSTER is
// keyed by the results' names (pseudonyms in an anonymised run, whose
// entries then hold the section only).
std::vector<std::string> attachRoster(ClassResult& result,
                                      const std::map<std::string, RosterEntry>& roster);

// result.mistakes: per catalogued mistake of the graded stages, how many
// graded stages failed exactly the checks it fails (seeded views aside).
void matchMistakes(ClassResult& result);

// The first MOST of NAMES, joined by ", ", then ", ..." when there are more
// (warnings about many students stay one line).
std::string firstFew(const std::vector<std::string>& names, std::size_t most = 5);

}  // namespace raylab
