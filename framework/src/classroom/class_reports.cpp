#include "class_reports.h"

#include "class_finish.h"
#include "class_roster.h"
#include "course_file.h"
#include "error.h"
#include "grade_report.h"
#include "grade_stage.h"
#include "pseudonyms.h"
#include "submission_times.h"

#include <cstdio>
#include <map>

namespace raylab {

namespace fs = std::filesystem;

namespace {

void printSummary(const ClassResult& result) {
    std::printf("\n%-24s", "student");
    for (const std::string& s : result.stages) std::printf(" %6.2s", s.c_str());
    std::printf(" %8s\n", "total");
    for (const StudentResult& st : result.students) {
        std::printf("%-24.24s", st.name.c_str());
        for (const StageResult& r : st.stages) {
            if (r.status == "graded") std::printf(" %6.1f", r.score);
            else if (r.status == "not submitted") std::printf(" %6s", "-");
            else
                std::printf(" %6s", r.status == "compile error" ? "CE"
                                    : r.status == "timed out"   ? "TIME"
                                                                : "ERR");
        }
        std::printf(" %8.1f\n", st.score());
    }
    std::printf("(scores out of 100 per stage; - not submitted, CE compile error, TIME timed out, "
                "ERR crashed or other error)\n");
}

// The class reports in OUT and the summary table on stdout.
void writeClassReports(const ClassResult& result, const fs::path& out) {
    for (const StudentResult& st : result.students) {
        if (!st.hasFolder) continue;  // only in the roster: nothing graded, no folder
        try {
            writeGradescopeResults(st, studentFolder(out, st.name) / "results.json");
        } catch (const Error& e) {  // one student's file must not cost the class its report
            std::fprintf(stderr, "raylab grade: %s\n", e.what());
        }
    }
    writeSummaryCsv(result, out / "summary.csv");
    writeJunitXml(result, out / "junit.xml");
    writeHtmlReport(result, out);
    printSummary(result);
}

}  // namespace

void finishAndReport(ClassResult result, const GradeOptions& g, const fs::path& out) {
    if (!g.course.empty()) {
        const CourseSettings course = readCourseFile(g.course);
        if (course.late) {
            if (g.submitted.empty())
                throw Error("--course " + g.course +
                            " has a late policy: give --submitted (a CSV, or mtime)");
            const SubmissionTimes times = SubmissionTimes::read(g.submitted, g.submissions);
            std::map<std::string, std::string> folderOf;  // result name -> the times' name
            if (result.anonymised) {
                if (g.anonymise.empty())
                    throw Error("the names are pseudonyms: a late policy needs --anonymise KEYFILE "
                                "to find each student's submission time");
                folderOf = PseudonymKey(g.anonymise).known();
            }
            applyLatePolicy(result, *course.late, times, folderOf);
        }
    }
    if (!g.roster.empty()) {
        const std::vector<std::string> unlisted = attachRoster(result, readRoster(g.roster));
        if (!unlisted.empty())
            std::fprintf(stderr,
                         "raylab grade: %zu student folder%s not in the roster (%s): no id in "
                         "summary.csv%s\n",
                         unlisted.size(), unlisted.size() == 1 ? " is" : "s are",
                         firstFew(unlisted).c_str(),
                         g.lms.empty() ? "" : ", left out of canvas.csv");
        std::string missing;
        for (const StudentResult& st : result.students)
            if (!st.hasFolder) missing += (missing.empty() ? "" : ", ") + st.name;
        if (!missing.empty())
            std::fprintf(stderr,
                         "raylab grade: in the roster without a submission folder (not "
                         "submitted; a typo?): %s\n",
                         missing.c_str());
    }
    matchMistakes(result);
    writeClassReports(result, out);
    std::error_code ec;
    if (g.lms.empty()) fs::remove(out / "canvas.csv", ec);  // never one of an earlier run
    if (g.lms == "canvas") {
        writeCanvasCsv(result, out / "canvas.csv", "RayLab ");
        std::printf("canvas.csv: import it in Canvas under Grades > Import\n");
    }
}

}  // namespace raylab
