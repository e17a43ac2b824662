#include "class_grading.h"

#include "class_file.h"
#include "class_reports.h"
#include "class_roster.h"
#include "course_file.h"
#include "error.h"
#include "grade_class.h"
#include "grade_shards.h"
#include "lab_folder.h"
#include "lms_exports.h"
#include "pseudonyms.h"
#include "submission_times.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// The options only a whole class's reports use, checked before any work.
void checkReportOptions(const GradeOptions& g) {
    parseLmsList(g.lms);  // an unknown LMS stops here
    if (!g.reason.empty() && g.only.empty())
        throw Error("--reason says why a student is regraded: it goes with --only NAME");
    if (!g.lms.empty() && g.roster.empty())
        throw Error("--lms " + g.lms +
                    " needs --roster FILE (an LMS matches students by their ids)");
    if (!g.anonymise.empty() && !g.lms.empty())
        throw Error("--anonymise cannot go with --lms: an LMS import names the students by their "
                    "ids");
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
    if (!g.roster.empty()) checkRosterServes(parseLmsList(g.lms), readRoster(g.roster));
    if (!g.course.empty()) readCourseFile(g.course);
    if (!g.submitted.empty() && g.submitted != "mtime")
        SubmissionTimes::read(g.submitted, g.submissions);
}

// What one student's stage shows in a regrade's log: the score as graded
// (before a late policy), or why there is none.
std::string outcome(const StageResult* s) {
    if (!s) return "no result";
    if (s->status != "graded") return s->status;
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", s->score);
    std::string t = text;
    t.erase(t.find_last_not_of('0') + 1);
    if (t.back() == '.') t.pop_back();
    return t;
}

// BEFORE's regrades (null: the student was not in the report) and this one.
std::vector<Regrade> regradeOf(const StudentResult* before, const StudentResult& after,
                               const std::string& reason) {
    std::vector<Regrade> history = before ? before->regrades : std::vector<Regrade>{};
    Regrade g{formatUtc(std::int64_t(std::time(nullptr))), reason, {}};
    for (const StageResult& s : after.stages) {
        const StageResult* old = nullptr;
        if (before)
            for (const StageResult& o : before->stages)
                if (o.stage == s.stage) old = &o;
        const std::string was = before ? outcome(old) : "not in the report";
        if (was != outcome(&s)) g.changes.push_back({s.stage, was, outcome(&s)});
    }
    history.push_back(std::move(g));
    return history;
}

}  // namespace

std::optional<double> gradeAndReport(const GradeOptions& options) {
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
    if (!graded) return std::nullopt;  // interrupted: no report
    ClassResult result = *graded;
    // Pseudonyms in their own order: the folders' (alphabetical) order would
    // let a class list tell whose each is.
    if (result.anonymised)
        std::sort(result.students.begin(), result.students.end(),
                  [](const StudentResult& a, const StudentResult& b) { return a.name < b.name; });
    // The reports; a share writes its results for --merge instead.
    if (!g.shard.empty()) {
        const Shard shard = parseShard(g.shard);
        writeShardFile(result, shard.index, shard.count, out);
        std::printf("graded share %d/%d (%zu students) in %.1f s; merge the shares with: raylab "
                    "grade --merge OUT SHARD_DIR...\n",
                    shard.index, shard.count, result.students.size(), result.seconds);
        return result.seconds;
    }
    const double thisRun = result.seconds;
    if (earlier) {
        // The one student's new results in place of the old, or added, and
        // the regrade in their history.
        StudentResult fresh = result.students.front();
        ClassResult merged = *earlier;
        auto it = std::find_if(merged.students.begin(), merged.students.end(),
                               [&](const StudentResult& s) { return s.name == fresh.name; });
        fresh.regrades = regradeOf(it == merged.students.end() ? nullptr : &*it, fresh, g.reason);
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
    return thisRun;
}

}  // namespace raylab
