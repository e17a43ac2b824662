#include "grade_class.h"

#include "atomic_file.h"
#include "child_process.h"
#include "class_file.h"
#include "course_file.h"
#include "error.h"
#include "grade_items.h"
#include "grade_shards.h"
#include "grade_stage.h"
#include "lms_exports.h"
#include "paths.h"
#include "pseudonyms.h"
#include "same_work.h"
#include "stage_list.h"

#include <csignal>
#include <functional>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <memory>
#include <optional>

namespace raylab {

namespace fs = std::filesystem;

namespace {

struct Item {
    std::size_t student;
    const StageInfo* stage;
};

}  // namespace

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

namespace {

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

volatile std::sig_atomic_t gInterrupted = 0;
extern "C" void onInterrupt(int) { gInterrupted = 1; }

// A regrade (--only) keeps the student's earlier results, pictures and logs:
// OUT/history/<name>/<n>/, n counting the regrades.
void keepEarlierResults(const fs::path& out, const std::string& name) {
    std::error_code ec;
    const fs::path folder = studentFolder(out, name);
    if (!fs::exists(folder, ec)) return;
    int n = 1;
    while (fs::exists(out / "history" / name / std::to_string(n), ec)) ++n;
    const fs::path kept = out / "history" / name / std::to_string(n);
    fs::create_directories(kept.parent_path(), ec);
    fs::rename(folder, kept, ec);
    if (ec)
        throw Error("--only " + name + ": cannot keep the earlier results in " + kept.string() +
                    " (" + ec.message() + ")");
}

}  // namespace

std::vector<std::string> classOutputs() {
    std::vector<std::string> files{"students",  "reference",   "history",
                                   "sections",  "report.html", "summary.csv",
                                   "junit.xml", "class.json",  "regrades.csv"};
    for (const std::string& lms : kLmsNames) files.push_back(lms + ".csv");
    return files;
}

std::vector<const StageInfo*> stagesToGrade(const std::string& list) {
    if (list.empty()) {
        std::vector<const StageInfo*> stages;
        for (const StageInfo& s : allStages()) stages.push_back(&s);
        return stages;
    }
    return parseStageList(list);
}

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
        keepEarlierResults(out, shown.front());
        referencesReady = true;
        for (const StageInfo* s : stages)
            referencesReady = referencesReady && fs::is_directory(out / "reference" / s->id, ec);
    } else {
        for (const std::string& own : classOutputs()) fs::remove_all(out / own, ec);
        fs::remove_all(out / "shard.json", ec);
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
    // An item whose work is an earlier item's is not run: it gets that
    // item's result (same_work.h).
    std::map<std::string, Item> leaderOf;       // work -> the item that grades it
    std::vector<std::pair<Item, Item>> sameAs;  // (item, its leader)
    for (std::size_t i = 0; i < students.size(); ++i) {
        result.students[i].name = shown[i];
        fs::create_directories(studentFolder(out, shown[i]), ec);
        const fs::path lab = submissions / students[i];
        for (const StageInfo* s : stages) {
            const std::optional<std::string> work =
                stageFolderExists(lab / s->id) ? sameWorkKey(*s, lab) : std::nullopt;
            if (work) {
                const auto [at, first] = leaderOf.emplace(*work, Item{i, s});
                if (!first) {
                    sameAs.emplace_back(Item{i, s}, at->second);
                    continue;
                }
            }
            queue.push_back({i, s});
        }
    }
    Progress progress(queue.size() + sameAs.size());
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
            // No student-facing text names the grading machine's folders
            // (or, anonymised, the student).
            const std::string& name = students[item.student];
            scrubNames(itemDir / "log.txt", name, shown[item.student], submissions);
            if (!haveResult) r = failedItem(*item.stage, o, itemDir / "log.txt", g);
            r.seconds = o.seconds;
            r.peakMb = o.peakMb;
            auto clean = [&](const std::string& text) {
                return g.anonymise.empty()
                           ? withoutMachinePath(text, name, submissions)
                           : withoutName(text, name, shown[item.student], submissions);
            };
            const std::string before = stageResultToJson(r);
            r.message = clean(r.message);
            for (CheckResult& c : r.checks) c.output = clean(c.output);
            if (haveResult && stageResultToJson(r) != before)
                writeTextFileAtomic(itemDir / "result.json", stageResultToJson(r));
            finish(item, r);
        };
        return runPool(items.size(), jobs, startItem, itemDone, interrupted);
    };
    // Grades ITEMS; false when interrupted.
    auto gradeItems = [&](const std::deque<Item>& items) {
        std::deque<Item> timedOut;
        bool completed = runItems(items, g.jobs, [&](const Item& item, StageResult r) {
            // With --jobs 1 the item ran alone already: a rerun would cost the
            // timeout again for the same verdict.
            if (r.status == "timed out" && g.jobs > 1) timedOut.push_back(item);
            else progress.done(students[item.student], r);
            graded[{item.student, item.stage->id}] = std::move(r);
        });
        // A wall-clock limit depends on the load: an item that timed out while
        // others ran beside it gets a second run on its own before it scores 0.
        // (Gradescope and PrairieLearn grade with --jobs 1: no second run.)
        if (completed && !timedOut.empty()) {
            std::fprintf(stderr, "raylab grade: %zu item%s timed out; running %s again on %s own\n",
                         timedOut.size(), timedOut.size() == 1 ? "" : "s",
                         timedOut.size() == 1 ? "it" : "them",
                         timedOut.size() == 1 ? "its" : "their");
            completed = runItems(timedOut, 1, [&](const Item& item, StageResult r) {
                progress.done(students[item.student], r);
                graded[{item.student, item.stage->id}] = std::move(r);
            });
        }
        return completed;
    };
    if (!gradeItems(queue)) return std::nullopt;
    // The same work's result for each student who handed it in; graded on
    // their own where the result names its student (same_work.h).
    std::deque<Item> ownRun;
    for (const auto& [item, leader] : sameAs) {
        std::optional<StageResult> r =
            copySameWork(graded.at({leader.student, leader.stage->id}), out, shown[leader.student],
                         shown[item.student], {students[leader.student], shown[leader.student]});
        if (!r) {
            ownRun.push_back(item);
            continue;
        }
        progress.done(students[item.student], *r);
        graded[{item.student, item.stage->id}] = std::move(*r);
    }
    if (!gradeItems(ownRun)) return std::nullopt;
    if (sameAs.size() > ownRun.size())
        std::printf("raylab grade: %zu of %zu items the same work as another student's: graded "
                    "once\n",
                    sameAs.size() - ownRun.size(), queue.size() + sameAs.size());
    for (std::size_t i = 0; i < students.size(); ++i)
        for (const StageInfo* s : stages) result.students[i].stages.push_back(graded[{i, s->id}]);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    return result;
}

}  // namespace raylab
