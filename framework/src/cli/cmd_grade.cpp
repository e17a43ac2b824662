// `raylab grade`: a whole class, headless. Every stage of every submission
// is graded in a child process of its own (cmd_grade_item.cpp) with a
// timeout and a memory limit, --jobs at a time; the results go to
// report.html, <student>/results.json (Gradescope), summary.csv and
// junit.xml. One bad submission never stops the run or touches another's
// score.
#include "atomic_file.h"
#include "child_process.h"
#include "class_finish.h"
#include "class_roster.h"
#include "command.h"
#include "commands.h"
#include "course_file.h"
#include "error.h"
#include "grade_report.h"
#include "grade_shards.h"
#include "grade_stage.h"
#include "paths.h"
#include "pseudonyms.h"
#include "stage_list.h"

#include <unistd.h>

#include <csignal>
#include <functional>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

namespace raylab {

namespace fs = std::filesystem;

namespace {

struct Item {
    std::size_t student;
    const StageInfo* stage;
};

std::vector<const StageInfo*> stagesToGrade(const std::string& list) {
    if (list.empty()) {
        std::vector<const StageInfo*> stages;
        for (const StageInfo& s : allStages()) stages.push_back(&s);
        return stages;
    }
    return parseStageList(list);
}

// The student folders, sorted. Symbolic links are skipped (a link could lead
// anywhere, also to the solution) and said so.
std::vector<std::string> studentFolders(const fs::path& submissions) {
    std::error_code ec;
    if (!fs::is_directory(submissions, ec))
        throw Error("--submissions '" + submissions.string() + "': no such folder");
    std::vector<std::string> names;
    for (fs::directory_iterator it(submissions, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        fs::file_type type = it->symlink_status(ec).type();
        if (name.empty() || name[0] == '.') continue;
        if (type == fs::file_type::symlink) {
            std::fprintf(stderr, "raylab grade: skipping %s: a symbolic link, not a folder\n",
                         name.c_str());
            continue;
        }
        if (type == fs::file_type::directory) names.push_back(name);
    }
    if (ec) throw Error("--submissions '" + submissions.string() + "': " + ec.message());
    if (names.empty())
        throw Error("--submissions '" + submissions.string() + "': no student folders in it");
    std::sort(names.begin(), names.end());
    return names;
}

// --out must not be --submissions or lie inside it (grading deletes and
// rewrites its own folders in --out), nor the other way round.
void checkFoldersApart(const fs::path& submissions, const fs::path& out) {
    std::error_code ec;
    fs::path a = fs::weakly_canonical(submissions, ec), b = fs::weakly_canonical(out, ec);
    auto within = [](const fs::path& inner, const fs::path& outer) {
        return std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end()).first ==
               outer.end();
    };
    if (within(b, a) || within(a, b))
        throw Error("--out '" + out.string() + "' and --submissions must be separate folders");
}

// A stage folder that is a real folder (not a link).
bool stageFolderExists(const fs::path& dir) {
    std::error_code ec;
    return fs::symlink_status(dir, ec).type() == fs::file_type::directory;
}

// Runs COUNT jobs with at most JOBS children at once. START(i) starts job i
// and returns its child, or nullptr when the job needed none (it is then
// finished already). DONE(i, outcome) runs when child i has ended. Returns
// false when INTERRUPTED() says so; the running children are then killed
// (~Child).
bool runPool(std::size_t count, int jobs,
             const std::function<std::unique_ptr<Child>(std::size_t)>& start,
             const std::function<void(std::size_t, const ChildOutcome&)>& done,
             const std::function<bool()>& interrupted) {
    std::vector<std::pair<std::size_t, std::unique_ptr<Child>>> running;
    std::size_t next = 0;
    while (next < count || !running.empty()) {
        if (interrupted()) return false;
        while (next < count && int(running.size()) < jobs) {
            std::size_t job = next++;
            if (auto child = start(job)) running.emplace_back(job, std::move(child));
        }
        bool any = false;
        for (auto it = running.begin(); it != running.end();) {
            if (!it->second->poll()) {
                ++it;
                continue;
            }
            any = true;
            done(it->first, it->second->outcome());
            it = running.erase(it);
        }
        if (!any) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

volatile std::sig_atomic_t gInterrupted = 0;
extern "C" void onInterrupt(int) { gInterrupted = 1; }

std::string lastLines(const fs::path& log, int count) {
    std::ifstream in(log);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    std::string out;
    for (std::size_t i = lines.size() > std::size_t(count) ? lines.size() - std::size_t(count) : 0;
         i < lines.size(); ++i)
        out += lines[i] + "\n";
    return out;
}

// What a child that left no result means.
StageResult failedItem(const StageInfo& stage, const ChildOutcome& o, const fs::path& log,
                       const GradeOptions& g) {
    StageResult r;
    r.stage = stage.id;
    r.seconds = o.seconds;
    char limit[160];
    if (o.timedOut) {
        r.status = "timed out";
        std::snprintf(limit, sizeof limit,
                      "stopped after %.0f s (--timeout): an endless loop, or a shader that takes "
                      "minutes to compile?",
                      g.timeoutSeconds);
        r.message = limit;
    } else if (o.exitCode == 3) {
        r.status = "out of memory";
        r.message =
            "ran out of memory (--memory-mb " + std::to_string(g.memoryMb) + "): a huge array?";
    } else if (o.signal) {
        r.status = "crashed";
        r.message = o.describe() +
                    " (a crash in the shader compiler or driver, or memory beyond --memory-mb " +
                    std::to_string(g.memoryMb) + ")";
    } else {
        r.status = "error";
        r.message = o.describe();
    }
    std::string tail = lastLines(log, 5);
    if (!tail.empty()) r.message += "\nlast lines of its log:\n" + tail;
    return r;
}

// On a terminal: a bar and the item now under work; in a log: a line per
// finished item.
class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), tty_(isatty(2)) {}
    void working(const std::string& student, const std::string& stage) {
        if (!tty_) return;
        const int width = 30;
        int filled =
            int(double(width) * double(finished_) / double(std::max<std::size_t>(total_, 1)));
        std::fprintf(stderr, "\r[%s%s] %zu/%zu  grading %-20.20s %-14s",
                     std::string(std::size_t(filled), '#').c_str(),
                     std::string(std::size_t(width - filled), '.').c_str(), finished_, total_,
                     student.c_str(), stage.c_str());
        std::fflush(stderr);
    }
    void done(const std::string& student, const StageResult& r) {
        ++finished_;
        if (tty_) {
            if (finished_ == total_) std::fprintf(stderr, "\r%-90s\r", "");
        } else {
            std::fprintf(stderr, "  [%zu/%zu] %s %s: %s\n", finished_, total_, student.c_str(),
                         r.stage.c_str(),
                         r.status == "graded"
                             ? (std::to_string(int(std::lround(r.score))) + "/100").c_str()
                             : r.status.c_str());
        }
        std::fflush(stderr);
    }

private:
    std::size_t total_, finished_ = 0;
    bool tty_;
};

// TEXT with the student's folder (as given, absolute, canonical) and name
// replaced by the pseudonym: compiler messages name the student's files.
std::string withoutName(std::string text, const std::string& name, const std::string& pseudonym,
                        const fs::path& submissions) {
    std::error_code ec;
    const fs::path folder = submissions / name;
    std::vector<std::string> forms = {fs::weakly_canonical(folder, ec).string(),
                                      fs::absolute(folder, ec).string(), folder.string(),
                                      displayPath(folder)};
    // The bare name too, where it is long enough not to hit ordinary words.
    if (name.size() >= 4) forms.push_back(name);
    for (const std::string& form : forms) {
        if (form.empty()) continue;
        // On after each replacement: the pseudonym may hold the name
        // ("stud" in "student-...").
        for (std::size_t at = text.find(form); at != std::string::npos;
             at = text.find(form, at + pseudonym.size()))
            text.replace(at, form.size(), pseudonym);
    }
    return text;
}

void scrubNames(const fs::path& log, const std::string& name, const std::string& pseudonym,
                const fs::path& submissions) {
    std::error_code ec;
    if (!fs::is_regular_file(log, ec)) return;
    const std::string text = readTextFile(log);
    const std::string clean = withoutName(text, name, pseudonym, submissions);
    if (clean != text) writeTextFileAtomic(log, clean);
}

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

}  // namespace

std::optional<ClassResult> gradeClass(const GradeOptions& g) {
    if (g.jobs < 1 || g.jobs > 64) throw Error("--jobs must be between 1 and 64");
    if (!(g.timeoutSeconds > 0.0) || g.timeoutSeconds > 3600.0)
        throw Error("--timeout must be between 0 and 3600 seconds");
    if (g.memoryMb != 0 && (g.memoryMb < 256 || g.memoryMb > 1 << 20))
        throw Error("--memory-mb must be 0 (no limit) or 256..1048576");
    if (g.outDir.empty()) throw Error("--out is required");
    const std::vector<const StageInfo*> stages = stagesToGrade(g.stages);
    const fs::path submissions = g.submissions;
    const Shard shard = g.shard.empty() ? Shard{} : parseShard(g.shard);
    // The course file is read here once, so that a mistake in it stops the
    // run before any work; the children read it again for the weights.
    std::string courseFile;
    if (!g.course.empty()) {
        readCourseFile(g.course);
        courseFile = fs::absolute(g.course).string();
    }
    std::vector<std::string> students = studentFolders(submissions);
    if (!g.only.empty()) {
        if (std::find(students.begin(), students.end(), g.only) == students.end())
            throw Error("--only " + g.only + ": no folder " + g.only + "/ in " +
                        submissions.string());
        students = {g.only};
    }
    if (shard.count > 1) {
        std::vector<std::string> mine;
        for (std::size_t i = 0; i < students.size(); ++i)
            if (inShard(i, shard)) mine.push_back(students[i]);
        if (mine.empty())
            std::printf("raylab grade: share %d/%d has no students (the class has %zu)\n",
                        shard.index, shard.count, students.size());
        students = std::move(mine);
    }
    const fs::path out = g.outDir;
    checkFoldersApart(submissions, out);
    // What the reports call each student: the folder's name, or its pseudonym.
    std::vector<std::string> shown;
    if (!g.anonymise.empty()) {
        PseudonymKey key(g.anonymise);
        for (const std::string& name : students) shown.push_back(key.pseudonym(name));
        key.save();
    } else {
        shown = students;
    }
    std::error_code ec;
    // Only what grading writes is cleared: no stale result of an earlier run
    // may be mixed into this one. A regrade of one student (--only) clears
    // that student's results and keeps the rest, the references included.
    bool referencesReady = false;
    if (!g.only.empty()) {
        fs::remove_all(studentFolder(out, shown.front()), ec);
        referencesReady = true;
        for (const StageInfo* s : stages)
            referencesReady = referencesReady && fs::is_directory(out / "reference" / s->id, ec);
    } else {
        for (const char* own : {"students", "reference", "report.html", "summary.csv", "junit.xml",
                                "shard.json", "class.json", "canvas.csv"})
            fs::remove_all(out / own, ec);
    }
    fs::create_directories(out / "reference", ec);
    if (ec) throw Error("--out '" + g.outDir + "': cannot create the folder");
    const std::string exe = executablePath().string();
    const std::string seed = std::to_string(g.seed);
    const auto start = std::chrono::steady_clock::now();
    // Ctrl-C or a kill: stop the children (their own process groups do not
    // get the terminal's signal) and leave no report that looks complete.
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    auto interrupted = [&] {
        if (!gInterrupted) return false;
        std::fprintf(stderr, "\nraylab grade: interrupted; no report was written (the folder holds "
                             "partial results only)\n");
        return true;
    };

    std::printf("raylab grade: %zu student%s x %zu stage%s%s, %d job%s, timeout %.0f s, memory "
                "%ld MB%s\n",
                students.size(), students.size() == 1 ? "" : "s", stages.size(),
                stages.size() == 1 ? "" : "s",
                shard.count > 1 ? (" (share " + std::to_string(shard.index) + "/" +
                                   std::to_string(shard.count) + ")")
                                      .c_str()
                                : "",
                g.jobs, g.jobs == 1 ? "" : "s", g.timeoutSeconds, g.memoryMb,
                g.seed == 0 ? ", seed 0 (give --seed N and keep it secret)" : "");
    std::fflush(stdout);

    // 1. The solution's images for every stage (trusted code, but in children
    //    too: they run in parallel and share nothing).
    const bool referencesDone = runPool(
        referencesReady ? 0 : stages.size(), g.jobs,
        [&](std::size_t i) {
            return std::make_unique<Child>(
                std::vector<std::string>{exe, "grade-reference", "--stage", stages[i]->id, "--out",
                                         out.string(), "--seed", seed},
                out / "reference" / (stages[i]->id + ".log"),
                ChildLimits{g.timeoutSeconds * 10.0, 0});
        },
        [&](std::size_t i, const ChildOutcome& o) {
            if (o.exitCode != 0)
                throw Error("rendering the reference images of stage " + stages[i]->id +
                            " failed (" + o.describe() + "); see " +
                            (out / "reference" / (stages[i]->id + ".log")).string());
        },
        interrupted);
    if (!referencesDone) return std::nullopt;

    // 2. Every stage of every submission.
    ClassResult result;
    result.seed = g.seed;
    for (const StageInfo* s : stages) result.stages.push_back(s->id);
    result.machine = lastLines(out / "reference" / "machine.txt", 1);
    if (!result.machine.empty()) result.machine.pop_back();
    result.students.resize(students.size());
    std::map<std::pair<std::size_t, std::string>, StageResult> graded;
    std::deque<Item> queue;
    result.anonymised = !g.anonymise.empty();
    result.courseDigest = fileDigest(g.course);
    for (std::size_t i = 0; i < students.size(); ++i) {
        result.students[i].name = shown[i];
        fs::create_directories(studentFolder(out, shown[i]), ec);
        for (const StageInfo* s : stages) queue.push_back({i, s});
    }
    Progress progress(queue.size());
    const ChildLimits limits{g.timeoutSeconds, g.memoryMb};
    // Runs ITEMS with up to JOBS children; FINISH gets each item's result.
    auto runItems = [&](const std::deque<Item>& items, int jobs,
                        const std::function<void(const Item&, StageResult)>& finish) {
        auto startItem = [&](std::size_t i) -> std::unique_ptr<Child> {
            const Item& item = items[i];
            const std::string& name = students[item.student];
            const fs::path stageDir = submissions / name / item.stage->id;
            if (!stageFolderExists(stageDir)) {
                StageResult r;
                r.stage = item.stage->id;
                r.status = fs::exists(stageDir, ec) ? "error" : "not submitted";
                r.message = r.status == "error"
                                ? item.stage->id + "/ is not a folder (a symbolic link?)"
                                : "no " + item.stage->id + "/ folder in the submission";
                finish(item, r);
                return nullptr;
            }
            const fs::path itemDir = studentFolder(out, shown[item.student]) / item.stage->id;
            fs::remove_all(itemDir, ec);  // a rerun starts clean: no stale result counts
            fs::create_directories(itemDir, ec);
            progress.working(name, item.stage->id);
            std::vector<std::string> args{exe,         "grade-item",
                                          "--stage",   item.stage->id,
                                          "--lab",     (submissions / name).string(),
                                          "--student", shown[item.student],
                                          "--out",     out.string(),
                                          "--seed",    seed};
            if (!courseFile.empty()) args.insert(args.end(), {"--course", courseFile});
            return std::make_unique<Child>(args, itemDir / "log.txt", limits);
        };
        auto itemDone = [&](std::size_t i, const ChildOutcome& o) {
            const Item& item = items[i];
            const fs::path itemDir = studentFolder(out, shown[item.student]) / item.stage->id;
            StageResult r;
            bool haveResult = false;
            if (!o.timedOut && o.exitCode == 0 && fs::exists(itemDir / "result.json", ec)) {
                try {
                    r = stageResultFromJson(readTextFile(itemDir / "result.json"));
                    haveResult = true;
                } catch (const Error&) {}
            }
            if (!g.anonymise.empty())
                scrubNames(itemDir / "log.txt", students[item.student], shown[item.student],
                           submissions);
            if (!haveResult) r = failedItem(*item.stage, o, itemDir / "log.txt", g);
            r.seconds = o.seconds;
            if (!g.anonymise.empty()) {
                r.message = withoutName(r.message, students[item.student], shown[item.student],
                                        submissions);
                for (CheckResult& c : r.checks)
                    c.output = withoutName(c.output, students[item.student], shown[item.student],
                                           submissions);
                if (haveResult) writeTextFileAtomic(itemDir / "result.json", stageResultToJson(r));
            }
            finish(item, r);
        };
        return runPool(items.size(), jobs, startItem, itemDone, interrupted);
    };
    std::deque<Item> timedOut;
    bool completed = runItems(queue, g.jobs, [&](const Item& item, StageResult r) {
        if (r.status == "timed out") timedOut.push_back(item);
        else progress.done(students[item.student], r);
        graded[{item.student, item.stage->id}] = std::move(r);
    });
    // A wall-clock limit depends on the load: an item that timed out while
    // others ran beside it gets a second run on its own before it scores 0.
    if (completed && !timedOut.empty()) {
        std::fprintf(stderr, "raylab grade: %zu item%s timed out; running %s again on %s own\n",
                     timedOut.size(), timedOut.size() == 1 ? "" : "s",
                     timedOut.size() == 1 ? "it" : "them", timedOut.size() == 1 ? "its" : "their");
        completed = runItems(timedOut, 1, [&](const Item& item, StageResult r) {
            progress.done(students[item.student], r);
            graded[{item.student, item.stage->id}] = std::move(r);
        });
    }
    if (!completed) return std::nullopt;
    for (std::size_t i = 0; i < students.size(); ++i)
        for (const StageInfo* s : stages) result.students[i].stages.push_back(graded[{i, s->id}]);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    return result;
}

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
        merged.seconds = result.seconds;
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
    std::printf("graded in %.1f s; report: %s\n", result.seconds,
                fs::absolute(out / "report.html").lexically_normal().c_str());
    return 0;
}

namespace {

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
        if (!unlisted.empty()) {
            std::string names;
            for (std::size_t i = 0; i < unlisted.size() && i < 5; ++i)
                names += (i ? ", " : "") + unlisted[i];
            std::fprintf(stderr,
                         "raylab grade: %zu student folder%s not in the roster (%s%s): no id in "
                         "summary.csv%s\n",
                         unlisted.size(), unlisted.size() == 1 ? " is" : "s are", names.c_str(),
                         unlisted.size() > 5 ? ", ..." : "",
                         g.lms.empty() ? "" : ", left out of canvas.csv");
        }
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
