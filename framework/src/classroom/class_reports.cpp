#include "class_reports.h"

#include "atomic_file.h"
#include "class_finish.h"
#include "class_roster.h"
#include "class_sections.h"
#include "course_file.h"
#include "error.h"
#include "grade_report.h"
#include "grade_stage.h"
#include "lms_exports.h"
#include "pseudonyms.h"
#include "submission_times.h"

#include <cstdio>
#include <map>
#include <optional>

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
            if (r.excused) std::printf(" %6s", "EX");
            else if (r.status == "graded") std::printf(" %6.1f", r.score);
            else if (r.status == "not submitted") std::printf(" %6s", "-");
            else
                std::printf(" %6s", r.status == "compile error" ? "CE"
                                    : r.status == "timed out"   ? "TIME"
                                                                : "ERR");
        }
        std::printf(" %8.1f\n", st.score());
    }
    std::printf("(scores out of 100 per stage; - not submitted, CE compile error, TIME timed out, "
                "ERR crashed or other error, EX excused)\n");
}

// OUT/regrades.csv when a student was regraded (--only), else none.
void writeRegradeLog(const ClassResult& result, const fs::path& file) {
    for (const StudentResult& st : result.students)
        if (!st.regrades.empty()) return writeTextFileAtomic(file, regradeCsv(result));
    std::error_code ec;
    fs::remove(file, ec);
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
    writeRegradeLog(result, out / "regrades.csv");
    ClassPageOptions page;
    page.sections = writeSectionReports(result, out);
    writeHtmlReport(result, out, page);
    printSummary(result);
}

}  // namespace

void finishAndReport(ClassResult result, const GradeOptions& g, const fs::path& out) {
    const CourseSettings course = g.course.empty() ? CourseSettings{} : readCourseFile(g.course);
    // Pseudonyms: the course file, the times and the roster know the folders.
    std::optional<PseudonymKey> key;
    std::map<std::string, std::string> folderOf;  // result name -> folder name
    if (result.anonymised) {
        const bool needsNames = course.late || !course.extensions.empty() ||
                                !course.excused.empty() || !g.roster.empty();
        if (g.anonymise.empty() && needsNames)
            throw Error("the names are pseudonyms: the course file's rules and the roster need "
                        "--anonymise KEYFILE to find each student");
        if (!g.anonymise.empty()) {
            key.emplace(g.anonymise);
            folderOf = key->known();
        }
    }
    if (!g.roster.empty()) {
        std::map<std::string, RosterEntry> roster = readRoster(g.roster);
        if (key) {
            // An anonymised run keeps the sections only, under the pseudonyms.
            std::map<std::string, RosterEntry> sections;
            for (const auto& [name, entry] : roster) {
                RosterEntry only;
                only.section = entry.section;
                sections[key->pseudonym(name)] = only;
            }
            key->save();
            roster = std::move(sections);
        }
        const std::vector<std::string> unlisted = attachRoster(result, roster);
        if (!unlisted.empty())
            std::fprintf(stderr,
                         "raylab grade: %zu student folder%s not in the roster (%s): no id in "
                         "summary.csv%s\n",
                         unlisted.size(), unlisted.size() == 1 ? " is" : "s are",
                         firstFew(unlisted).c_str(),
                         g.lms.empty() ? "" : ", left out of the LMS exports");
        std::vector<std::string> missing;
        for (const StudentResult& st : result.students)
            if (!st.hasFolder) missing.push_back(st.name);
        if (!missing.empty())
            std::fprintf(stderr,
                         "raylab grade: %zu in the roster without a submission folder (not "
                         "submitted; a typo?): %s\n",
                         missing.size(), firstFew(missing, 10).c_str());
    }
    std::optional<SubmissionTimes> times;
    if (course.late) {
        if (g.submitted.empty())
            throw Error("--course " + g.course +
                        " has a late policy: give --submitted (a CSV, or mtime)");
        times = SubmissionTimes::read(g.submitted, g.submissions);
    }
    // After the roster: its students without a folder may be excused too.
    if (key) folderOf = key->known();
    applyCourseRules(result, course, times ? &*times : nullptr, folderOf);
    matchMistakes(result);
    writeClassReports(result, out);
    writeLmsExports(result, parseLmsList(g.lms), course.lms, out);
}

}  // namespace raylab
