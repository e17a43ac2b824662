// `raylab grade`: a whole class, headlessly. The options are parsed here;
// the work is the classroom module's (class_grading.h: every stage of every
// submission in a child process of its own, then report.html,
// <student>/results.json, summary.csv and junit.xml in --out).
#include "class_grading.h"
#include "command.h"
#include "error.h"
#include "grade_estimate.h"
#include "grade_shards.h"

#include <cstdio>
#include <memory>
#include <optional>

namespace raylab {

namespace fs = std::filesystem;

Command gradeCommand() {
    return {
        "grade", "grade a whole class headlessly: one folder per student, each laid out like labs/",
        [](CLI::App& cmd) {
            auto g = std::make_shared<GradeOptions>();
            auto merge = std::make_shared<std::vector<std::string>>();
            auto estimate = std::make_shared<bool>(false);
            auto sample = std::make_shared<std::size_t>(3);
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
                           "report in OUT (with --course, --roster, --submitted CSV, --lms, "
                           "--anonymise only)")
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
                           "canvas_id, login_id, section, email: ids in summary.csv, a report per "
                           "section, and what --lms needs");
            cmd.add_option("--lms", g->lms,
                           "also write the gradebook import of these LMSs, OUT/<lms>.csv: canvas, "
                           "moodle, blackboard, brightspace (a list: canvas,moodle)");
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
                           "report is rewritten; the earlier results are kept in "
                           "OUT/history/NAME/ and the regrade logged in OUT/regrades.csv)");
            cmd.add_option("--reason", g->reason,
                           "with --only: why the student is regraded (the regrade's log)");
            cmd.add_flag("--estimate", *estimate,
                         "grade a sample of the class (--sample) in a scratch folder and say "
                         "what the whole class will cost: time on this machine, per Slurm "
                         "task, per Gradescope upload, and memory");
            cmd.add_option("--sample", *sample, "with --estimate: how many students to grade")
                ->capture_default_str();
            return std::function<int()>([=] {
                if (!merge->empty()) {
                    if (!g->submissions.empty() || !g->outDir.empty() || !g->shard.empty() ||
                        !g->only.empty())
                        throw Error("--merge takes no --submissions, --out, --shard or --only");
                    if (g->submitted == "mtime")
                        throw Error(
                            "--merge: --submitted mtime needs the class folder; give a CSV");
                    mergeShards(*merge, *g);
                    std::printf("merged; report: %s\n",
                                fs::absolute(fs::path(merge->front()) / "report.html")
                                    .lexically_normal()
                                    .c_str());
                    return 0;
                }
                if (g->submissions.empty()) throw Error("--submissions is required");
                if (*estimate) {
                    if (!g->outDir.empty() || !g->only.empty() || !g->shard.empty())
                        throw Error("--estimate writes no report: it takes no --out, --only or "
                                    "--shard");
                    return estimateClass(*g, *sample) ? 0 : 130;
                }
                if (g->outDir.empty()) throw Error("--out is required");
                const std::optional<double> seconds = gradeAndReport(*g);
                if (!seconds) return 130;  // interrupted: no report
                if (g->shard.empty())
                    std::printf("graded in %.1f s; report: %s\n", *seconds,
                                fs::absolute(fs::path(g->outDir) / "report.html")
                                    .lexically_normal()
                                    .c_str());
                return 0;
            });
        }};
}

}  // namespace raylab
