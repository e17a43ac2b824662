// `raylab grade`: a whole class, headless. Every stage of every submission
// is graded in a child process of its own (gradeClass, grade_class.cpp) with
// a timeout and a memory limit, --jobs at a time; the results go to
// report.html, <student>/results.json (Gradescope), summary.csv and
// junit.xml. One bad submission never stops the run or touches another's
// score.
#include "class_finish.h"
#include "class_roster.h"
#include "command.h"
#include "commands.h"
#include "course_file.h"
#include "error.h"
#include "grade_report.h"
#include "grade_shards.h"
#include "grade_stage.h"
#include "lab_folder.h"
#include "paths.h"
#include "pseudonyms.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// The options only a whole class's reports use, checked before any work.
void checkReportOptions(const GradeOptions& g) {
    if (!g.lms.empty() && g.lms != "canvas")
        throw Error("--lms must be canvas (the one LMS import written so far), not '" + g.lms +
                    "'");
    if (!g.lms.empty() && g.roster.empty())
        throw Error("--lms canvas needs --roster FILE (Canvas matches students by their ids)");
    if (!g.anonymise.empty() && (!g.roster.empty() || !g.lms.empty()))
        throw Error("--anonymise cannot go with --roster or --lms: their ids name the students");
    if (!g.anonymise.empty()) {
        // The key must not reach the TAs with the report.
        std::error_code ec;
        const fs::path key = fs::weakly_canonical(g.anonymise, ec);
        for (const std::string& folder : {g.outDir, g.submissions}) {
            if (folder.empty()) continue;
            fs::path f = fs::weakly_canonical(folder, ec);
            if (f.filename().empty()) f = f.parent_path();  // "graded/" is the folder graded
            if (std::mismatch(f.begin(), f.end(), key.begin(), key.end()).first == f.end())
                throw Error("--anonymise " + g.anonymise + ": keep the key file outside " + folder +
                            " (whoever has it can tell whose each pseudonym is)");
        }
        PseudonymKey check(g.anonymise);  // a file that is not a key stops here
    }
    if (!g.submitted.empty() && (g.course.empty() || !readCourseFile(g.course).late))
        std::fprintf(stderr, "raylab grade: --submitted is used by a course file's late policy; "
                             "there is none, so it changes nothing\n");
    if (g.shard.empty() && !g.course.empty() && readCourseFile(g.course).late &&
        g.submitted.empty())
        throw Error("--course " + g.course +
                    " has a late policy: say when each student submitted, --submitted CSV "
                    "(student,submitted[,stage]) or --submitted mtime (the stage folders' "
                    "modification times, when they were kept)");
    if (!g.roster.empty()) readRoster(g.roster);
    if (!g.course.empty()) readCourseFile(g.course);
    if (!g.submitted.empty() && g.submitted != "mtime")
        SubmissionTimes::read(g.submitted, g.submissions);
}

}  // namespace

int cmdGrade(const GradeOptions& options) {
    // "The lab as handed out" (grade_stage.cpp) at the course's level, in
    // this process and the stages' child processes.
    setHandedOutLevel(parseLevel(options.level));
    const fs::path out = options.outDir;
    if (!options.shard.empty() && !options.only.empty())
        throw Error("--only and --shard exclude each other");
    // --only: the earlier run's results, checked to be of the same grading,
    // and its course file, roster, times and export, unless given again.
    GradeOptions g = options;
    std::optional<ClassResult> earlier;
    if (!g.only.empty()) {
        FinishSettings before;
        earlier = readClassFile(out, &before);
        if (g.course.empty()) g.course = before.course;
        if (g.roster.empty()) g.roster = before.roster;
        if (g.submitted.empty()) g.submitted = before.submitted;
        if (g.lms.empty()) g.lms = before.lms;
        std::error_code ec;
        if (!g.course.empty() && !fs::is_regular_file(g.course, ec))
            throw Error("--only: " + out.string() + " was graded with --course " + g.course +
                        ", which is gone; give it again");
        if (earlier->courseDigest != fileDigest(g.course))
            throw Error("--only: " + out.string() + " was graded " +
                        (earlier->courseDigest.empty() ? std::string("without a course file")
                                                       : "with another course file's weights") +
                        "; one report cannot mix weights (grade the class again)");
        if (earlier->seed != g.seed)
            throw Error("--only: " + out.string() + " was graded with --seed " +
                        std::to_string(earlier->seed) + ", not " + std::to_string(g.seed) +
                        " (its views would differ from the other students')");
        if (earlier->anonymised != !g.anonymise.empty())
            throw Error(std::string("--only: ") + out.string() + " was graded " +
                        (earlier->anonymised ? "with --anonymise KEYFILE: give it again"
                                             : "without --anonymise"));
        std::vector<std::string> ids;
        for (const StageInfo* s : stagesToGrade(g.stages)) ids.push_back(s->id);
        if (!g.stages.empty() && ids != earlier->stages)
            throw Error("--only: " + out.string() +
                        " graded other stages; give its --stages or none");
    }
    checkReportOptions(g);
    GradeOptions run = g;
    if (earlier) {
        run.stages.clear();
        for (const std::string& id : earlier->stages)
            run.stages += (run.stages.empty() ? "" : ",") + id;
    }
    const std::optional<ClassResult> graded = gradeClass(run);
    if (!graded) return 130;  // interrupted: no report
    ClassResult result = *graded;
    // Pseudonyms in their own order: the folders' (alphabetical) order would
    // let a class list tell whose each is.
    if (result.anonymised)
        std::sort(result.students.begin(), result.students.end(),
                  [](const StudentResult& a, const StudentResult& b) { return a.name < b.name; });
    // The reports; a share writes its results for --merge instead.
    if (!g.shard.empty()) {
        const Shard shard = parseShard(g.shard);
        writeShardFile(result, shard, out);
        std::printf("graded share %d/%d (%zu students) in %.1f s; merge the shares with: raylab "
                    "grade --merge OUT SHARD_DIR...\n",
                    shard.index, shard.count, result.students.size(), result.seconds);
        return 0;
    }
    const double thisRun = result.seconds;
    if (earlier) {
        // The one student's new results in place of the old, or added.
        const StudentResult fresh = result.students.front();
        ClassResult merged = *earlier;
        auto it = std::find_if(merged.students.begin(), merged.students.end(),
                               [&](const StudentResult& s) { return s.name == fresh.name; });
        if (it == merged.students.end()) merged.students.push_back(fresh);
        else *it = fresh;
        std::sort(merged.students.begin(), merged.students.end(),
                  [](const StudentResult& a, const StudentResult& b) { return a.name < b.name; });
        std::printf("raylab grade --only %s: regraded in %.1f s; the other %zu students' results "
                    "are as they were\n",
                    g.only.c_str(), result.seconds, merged.students.size() - 1);
        // The report's wall time stays the class run's: a regrade of one
        // student is said above, not passed off as the whole class's time.
        result = merged;
    }
    // Absolute paths: --only may run from another folder.
    auto absolute = [](const std::string& p) {
        return p.empty() || p == "mtime" ? p : fs::absolute(p).lexically_normal().string();
    };
    writeClassFile(result,
                   {absolute(g.course), "", absolute(g.roster), "", absolute(g.submitted), g.lms},
                   out);
    finishAndReport(result, g, out);
    std::printf("graded in %.1f s; report: %s\n", thisRun,
                fs::absolute(out / "report.html").lexically_normal().c_str());
    return 0;
}

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

Command gradeCommand() {
    return {
        "grade", "grade a whole class headlessly: one folder per student, each laid out like labs/",
        [](CLI::App& cmd) {
            auto g = std::make_shared<GradeOptions>();
            auto merge = std::make_shared<std::vector<std::string>>();
            cmd.add_option("--submissions", g->submissions,
                           "folder with one subfolder per student");
            cmd.add_option(
                "--out", g->outDir,
                "folder for report.html, summary.csv, junit.xml, <student>/results.json");
            cmd.add_option("--stages", g->stages,
                           "the stages to grade, as handout takes them: 01-03, 01,02,f1 or all "
                           "(default: all)");
            cmd.add_option("--jobs", g->jobs, "submissions graded at once")->capture_default_str();
            cmd.add_option("--timeout", g->timeoutSeconds, "seconds per stage of a submission")
                ->capture_default_str();
            cmd.add_option("--memory-mb", g->memoryMb,
                           "address-space limit per stage of a submission, MB (0: none)")
                ->capture_default_str();
            cmd.add_option("--seed", g->seed, "seed of the extra camera views (keep it secret)")
                ->capture_default_str();
            cmd.add_option("--shard", g->shard,
                           "grade share K of N (every N-th student from the K-th, 0-based) and "
                           "write shard.json for --merge");
            cmd.add_option("--merge", *merge,
                           "OUT SHARD_DIR...: put the shares of a --shard run together into one "
                           "report in OUT (with --course, --roster, --submitted CSV, --lms only)")
                ->expected(2, 100000);
            cmd.add_option("--course", g->course,
                           "a course file: weights over stage.json's, a late policy "
                           "(docs/grading.md)");
            cmd.add_option("--submitted", g->submitted,
                           "when each student submitted, for a late policy: a CSV "
                           "(student,submitted[,stage]) or mtime (the folders' times; the "
                           "default)");
            cmd.add_option("--roster", g->roster,
                           "a CSV with a student column (the folder names) and id, name, "
                           "canvas_id, login_id, section: ids in summary.csv, and for --lms");
            cmd.add_option("--lms", g->lms, "also write OUT/canvas.csv, Canvas's gradebook import")
                ->check(CLI::IsMember({"canvas"}));
            cmd.add_option("--anonymise,--anonymize", g->anonymise,
                           "KEYFILE: pseudonyms instead of folder names in every report file, "
                           "for TAs; KEYFILE (made when missing; keep it outside --out) holds the "
                           "key and whose each pseudonym is");
            cmd.add_option("--level", g->level,
                           "the level of the labs handed out, guided or open (raylab handout "
                           "--level): a picture still equal to the lab as handed out earns "
                           "nothing")
                ->capture_default_str();
            cmd.add_option("--only", g->only,
                           "regrade this one student into the existing report in --out (the "
                           "report is rewritten; nothing else changes)");
            return std::function<int()>([=] {
                if (!merge->empty()) {
                    if (!g->submissions.empty() || !g->outDir.empty() || !g->shard.empty() ||
                        !g->only.empty())
                        throw Error("--merge takes no --submissions, --out, --shard or --only");
                    if (g->submitted == "mtime")
                        throw Error(
                            "--merge: --submitted mtime needs the class folder; give a CSV");
                    return cmdGradeMerge(*merge, *g);
                }
                if (g->submissions.empty()) throw Error("--submissions is required");
                if (g->outDir.empty()) throw Error("--out is required");
                return cmdGrade(*g);
            });
        }};
}

}  // namespace raylab
