#pragma once
// What the report's HTML pages share (html_class_page.cpp, the class and its
// sections; html_student_page.cpp, one student): the style sheet, the page
// frame, the colours of a score. Not for use outside the reports.
#include "grade_result.h"

#include <string>

namespace raylab::report {

// <!DOCTYPE html> ... <main>: TITLE in <title> and <h1>, META (markup) under it.
std::string pageStart(const std::string& title, const std::string& meta);
std::string pageEnd();

// "ok" (at least 90%), "warn" (at least 50%) or "bad": a score's colour.
const char* tone(double score, double maxScore);
// The colour of a stage that was not graded ("none": not submitted).
const char* statusTone(const StageResult& s);
// A small bar filled to SCORE / MAXSCORE, hidden from screen readers (the
// number beside it says the same).
std::string bar(double score, double maxScore);

// A student's page, relative to the folder holding students/:
// "students/<name>/report.html", the name percent-encoded.
std::string studentPage(const std::string& name);
// The id of a stage's part of a student's page: "01-raycast".
std::string stageAnchor(const std::string& stage);

// What the class table shows for a stage: the score, or why there is none.
std::string stageCellText(const StageResult& s);

}  // namespace raylab::report
