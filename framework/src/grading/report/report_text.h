#pragma once
// Text helpers shared by the report writers of this folder (one writer per
// format: gradescope_results.cpp, summary_csv.cpp, junit_xml.cpp,
// html_report.cpp). Not for use outside the reports.
#include "grade_result.h"

#include <functional>
#include <string>
#include <string_view>
#include <utility>

namespace raylab::report {

// Scores as written everywhere: rounded to 2 decimals, never NaN/Inf or -0.
double round2(double v);

// "87.5", "100", "0.33": at most 2 decimals, no trailing zeros, no locale.
std::string num(double v);

double fraction(double score, double maxScore);

// "4.2 s", "3 min 07 s", "1 h 02 min".
std::string duration(double seconds);

// Valid UTF-8 that XML 1.0 and HTML accept: invalid byte sequences, control
// characters other than tab/newline/CR, and U+FFFE/U+FFFF become U+FFFD.
// Student folder names and compiler logs can hold anything.
std::string cleanText(std::string_view s);

// Text for XML/HTML element content and attribute values (either quote).
// ATTRIBUTE also keeps tab/newline/CR through attribute-value normalisation.
std::string escapeMarkup(std::string_view s, bool attribute = false);

// A relative path as a URL path: every byte but unreserved characters and '/'
// percent-encoded, so that '#', '?', ':' or spaces in a student's folder name
// cannot change what the link points to.
std::string urlPath(std::string_view path);

std::string firstLine(const std::string& s);

bool isGraded(const StageResult& s);

// The status word shown for a stage ("compile error"), never empty.
std::string statusWord(const StageResult& s);

// The student's result for stage ID, or null.
const StageResult* findStage(const StudentResult& student, const std::string& id);

// An LMS gradebook's cell for stage ID: the score after any late penalty;
// EXCUSED for an excused stage; empty when not submitted or not graded at all
// (an LMS leaves an empty cell's grade as it is).
std::string gradebookCell(const StudentResult& student, const std::string& id,
                          const std::string& excused = "");

// An LMS import's rows: ROW(student) for each student MATCHABLE says that
// LMS can match (by the roster's ids), in ClassResult order. Throws
// Error(NOMATCH) when there is none.
std::string gradebookRows(const ClassResult& result,
                          const std::function<bool(const RosterEntry&)>& matchable,
                          const std::function<std::string(const StudentResult&)>& row,
                          const std::string& noMatch);

// "Last, First" (the roster's name, as LMSs write it) -> {last, first};
// a name without a comma is all last name.
std::pair<std::string, std::string> lastAndFirst(const std::string& fullName);

// A CSV text field (csv_text.h) of cleaned text.
std::string csvField(const std::string& raw);

}  // namespace raylab::report
