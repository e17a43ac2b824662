// `raylab mutants`: how much of what students write do the checks test?
// Makes single-token mutants of a stage's //@solution code (mutants.h),
// lays each out as a student's lab of that stage (the solved lab with the one
// change) and grades them all with the class grader (gradeClass: sandboxed,
// with its timeouts and crash handling), so that a mutant meets exactly what
// a student's submission meets. A mutant scoring under 100 is caught; one
// scoring 100 survived: a skill the checks miss, or an equivalent mutant.
// Survivors explained in tests/mutants/<stage>.txt (known_survivors.h) pass
// --known; any other makes the exit code 1.
#include "atomic_file.h"
#include "command.h"
#include "commands.h"
#include "error.h"
#include "grade_class.h"
#include "known_survivors.h"
#include "lab_files.h"
#include "mutants.h"
#include "paths.h"
#include "stage_catalog.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace raylab {

namespace fs = std::filesystem;

namespace {

struct MutantsOptions {
    std::string stage;  // an id, or "all"
    std::string outDir;
    std::string knownDir;  // tests/mutants: <stage>.txt files; empty: no check
    long max = 0;          // 0: every mutant
    unsigned seed = 0;     // of the sample and of grading's seeded views
    int jobs = 2;
    double timeoutSeconds = 60.0;
};

// One stage's mutants, ready to grade.
struct StagePlan {
    const StageInfo* stage = nullptr;
    std::map<std::string, std::string> solvedLab;  // file -> text
    std::map<std::string, std::string> marked;     // own file -> marked solution text
    std::size_t total = 0;                         // before --max
    std::vector<Mutant> mutants;
    std::map<std::string, KnownSurvivor> known;
    std::string knownFile;  // "" when there is no --known
};

struct Verdict {
    bool caught = false;
    std::string by;  // "checks", "compiler", "limits", "error"
    std::string detail;
};

std::string lineOf(const std::string& text, int line) {
    std::istringstream in(text);
    std::string s;
    for (int n = 1; std::getline(in, s); ++n)
        if (n == line) return s;
    return {};
}

std::string studentName(std::size_t i) {
    char name[24];
    std::snprintf(name, sizeof name, "m%04zu", i + 1);
    return name;
}

StagePlan planStage(const StageInfo& stage, const MutantsOptions& o) {
    StagePlan p;
    p.stage = &stage;
    p.solvedLab = labFiles(stage, MarkedForm::Solved);
    std::vector<Mutant> all;
    for (const auto& [name, file] : labFileSources(stage)) {
        if (!file.own) continue;
        p.marked[name] = readTextFile(file.source);
        for (Mutant& m : generateMutants(name, p.marked[name])) all.push_back(std::move(m));
    }
    p.total = all.size();
    p.mutants = sampleMutants(all, std::size_t(o.max), o.seed);
    if (!o.knownDir.empty()) {
        const fs::path file = fs::path(o.knownDir) / (stage.id + ".txt");
        p.knownFile = file.string();
        std::error_code ec;
        if (fs::exists(file, ec)) p.known = parseKnownSurvivors(readTextFile(file), p.knownFile);
    }
    return p;
}

void writeLab(const fs::path& studentDir, const StageInfo& stage,
              const std::map<std::string, std::string>& files) {
    fs::create_directories(studentDir / stage.id);
    for (const auto& [name, text] : files) writeTextFileAtomic(studentDir / stage.id / name, text);
}

Verdict verdictOf(const StageResult& r) {
    Verdict v;
    if (r.status == "graded") {
        v.caught = r.score < r.maxScore - 1e-9;
        v.by = v.caught ? "checks" : "";
        for (const CheckResult& c : r.checks)
            if (!c.passed) v.detail += (v.detail.empty() ? "" : ", ") + c.name;
    } else if (r.status == "compile error") {
        v.caught = true;
        v.by = "compiler";
    } else if (r.status == "timed out" || r.status == "crashed" || r.status == "out of memory") {
        v.caught = true;
        v.by = "limits";
        v.detail = r.status;
    } else {  // "error": shown apart, as it may be the grader's fault rather than the mutant's
        v.caught = true;
        v.by = "error";
        v.detail = r.message.substr(0, r.message.find('\n'));
    }
    return v;
}

// Markdown table cells: a "|" (the || operator) would end the cell.
std::string cell(const std::string& s) {
    std::string out;
    for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string changeText(const Mutant& m) {
    return "`" + cell(m.from) + "` -> " + (m.to.empty() ? "(nothing)" : "`" + cell(m.to) + "`");
}

struct StageOutcome {
    std::size_t caught = 0, byChecks = 0, byCompiler = 0, byLimits = 0, byError = 0;
    std::vector<std::string> survivors;  // ids
};

std::string report(const StagePlan& p, const std::vector<Verdict>& verdicts, const StageOutcome& s,
                   const MutantsOptions& o) {
    const std::size_t n = p.mutants.size();
    std::ostringstream md;
    md << "# Mutants of stage " << p.stage->id << "\n\n"
       << "`" << programCommandLine() << "`: " << n << " of the stage's " << p.total
       << " single-token mutants of its `//@solution` code"
       << (n < p.total ? " (a sample, seed " + std::to_string(o.seed) + ")" : "")
       << ", each graded like a submission (grading seed " << o.seed << ").\n\n"
       << "**Caught " << s.caught << " of " << n << "**: " << s.byChecks << " by the checks, "
       << s.byCompiler << " by the compiler, " << s.byLimits
       << " by the limits (timeout, crash, memory), " << s.byError
       << " by another error of grading. " << s.survivors.size() << " survived (score 100).\n\n"
       << "| # | where | change | result | by |\n| --- | --- | --- | --- | --- |\n";
    for (std::size_t i = 0; i < n; ++i) {
        const Mutant& m = p.mutants[i];
        const Verdict& v = verdicts[i];
        md << "| " << studentName(i) << " | " << m.file << ":" << m.line << " | " << changeText(m)
           << " | " << (v.caught ? "caught" : "**survived**") << " | "
           << (v.caught ? v.by + (v.detail.empty() ? "" : ": " + cell(v.detail)) : "") << " |\n";
    }
    if (!s.survivors.empty()) md << "\n## Survivors\n";
    for (std::size_t i = 0; i < n; ++i) {
        if (verdicts[i].caught) continue;
        const Mutant& m = p.mutants[i];
        const std::string before = lineOf(p.marked.at(m.file), m.line);
        const std::string after = lineOf(applyMutant(p.marked.at(m.file), m), m.line);
        auto known = p.known.find(mutantId(m));
        md << "\n### " << studentName(i) << ": " << m.file << ":" << m.line << "\n\n"
           << "`" << mutantId(m) << "`"
           << (known != p.known.end()
                   ? "\n\nListed: " + known->second.reason
                   : std::string(p.knownFile.empty() ? "" : "\n\nNot listed in " + p.knownFile))
           << "\n\n```diff\n--- solution/" << p.stage->id << "/" << m.file << "\n+++ mutant "
           << studentName(i) << "\n@@ line " << m.line << " @@\n-" << before << "\n+" << after
           << "\n```\n";
    }
    return md.str();
}

// Mutates, grades and reports one stage into OUT, and adds its counts to
// TOTAL. Returns the exit code.
int runStage(const StagePlan& p, const fs::path& out, const MutantsOptions& o,
             StageOutcome& total) {
    const StageInfo& stage = *p.stage;
    const std::size_t n = p.mutants.size();
    if (n == 0) {
        std::printf("%s: no //@solution code to mutate\n", stage.id.c_str());
        return 0;
    }
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw Error("--out '" + out.string() + "': cannot create the folder");
    const fs::path submissions = out / "submissions";
    fs::remove_all(submissions, ec);  // only our own folder: no stale mutant is graded
    // A failed run must not leave an earlier run's verdicts looking current.
    fs::remove(out / "mutants.md", ec);
    fs::remove(out / "survivors.txt", ec);
    // "original" (the solution itself) proves the grader gives it 100: else
    // every mutant would look caught.
    writeLab(submissions / "original", stage, p.solvedLab);
    for (std::size_t i = 0; i < n; ++i) {
        const Mutant& m = p.mutants[i];
        std::map<std::string, std::string> files = p.solvedLab;
        files[m.file] =
            transformMarkedSource(applyMutant(p.marked.at(m.file), m), MarkedForm::Solved, m.file);
        writeLab(submissions / studentName(i), stage, files);
    }
    std::printf("raylab mutants: %s: grading %zu of %zu mutants\n", stage.id.c_str(), n, p.total);
    std::fflush(stdout);

    GradeOptions g;
    g.submissions = submissions.string();
    g.outDir = (out / "grade").string();
    g.stages = stage.id;
    g.jobs = o.jobs;
    g.timeoutSeconds = o.timeoutSeconds;
    g.seed = o.seed;
    const std::optional<ClassResult> graded = gradeClass(g);
    if (!graded) return 130;
    std::map<std::string, StageResult> byName;
    for (const StudentResult& st : graded->students) byName[st.name] = st.stages.at(0);
    const StageResult& original = byName.at("original");
    if (original.status != "graded" || original.score < original.maxScore - 1e-9)
        throw Error(
            stage.id + ": the unmutated solution scores " +
            (original.status == "graded" ? std::to_string(original.score) : original.status) +
            ", not 100, so no mutant can be judged; see " +
            (out / "grade" / "students" / "original").string());

    StageOutcome s;
    std::vector<Verdict> verdicts;
    std::string survivorsText = "# Survivors of raylab mutants --stage " + stage.id + " (seed " +
                                std::to_string(o.seed) + ", " + std::to_string(n) + " of " +
                                std::to_string(p.total) + " mutants graded)\n";
    for (std::size_t i = 0; i < n; ++i) {
        Verdict v = verdictOf(byName.at(studentName(i)));
        if (v.caught) {
            ++s.caught;
            ++(v.by == "checks"     ? s.byChecks
               : v.by == "compiler" ? s.byCompiler
               : v.by == "limits"   ? s.byLimits
                                    : s.byError);
        } else {
            s.survivors.push_back(mutantId(p.mutants[i]));
            survivorsText += s.survivors.back() + "\n";
        }
        verdicts.push_back(v);
    }
    total.caught += s.caught;
    total.byChecks += s.byChecks;
    total.byCompiler += s.byCompiler;
    total.byLimits += s.byLimits;
    total.byError += s.byError;
    total.survivors.insert(total.survivors.end(), s.survivors.begin(), s.survivors.end());
    writeTextFileAtomic(out / "mutants.md", report(p, verdicts, s, o));
    writeTextFileAtomic(out / "survivors.txt", survivorsText);
    std::printf(
        "%s: caught %zu of %zu (%zu by the checks, %zu by the compiler, %zu by the limits%s); "
        "%zu survived: %s\n",
        stage.id.c_str(), s.caught, n, s.byChecks, s.byCompiler, s.byLimits,
        s.byError ? (", " + std::to_string(s.byError) + " by other errors").c_str() : "",
        s.survivors.size(), (out / "mutants.md").c_str());

    if (p.knownFile.empty()) {
        // Survivors listed without reasons: say where the reasons are.
        if (!s.survivors.empty())
            std::printf("  %zu survivor%s listed without a reason: many are equivalent mutants "
                        "(no picture can tell them from the solution); --known tests/mutants "
                        "explains the known ones and fails only on new ones\n",
                        s.survivors.size(), s.survivors.size() == 1 ? "" : "s");
        return 0;
    }
    for (std::size_t i = 0; i < n; ++i)
        if (verdicts[i].caught && p.known.count(mutantId(p.mutants[i])))
            std::printf("  caught now, remove it from %s: %s\n", p.knownFile.c_str(),
                        mutantId(p.mutants[i]).c_str());
    const std::vector<std::string> unlisted = unlistedSurvivors(s.survivors, p.known);
    for (const std::string& id : unlisted)
        std::printf("  NEW SURVIVOR, not in %s: %s\n", p.knownFile.c_str(), id.c_str());
    if (!unlisted.empty())
        std::printf("%s: %zu survivor%s not explained in %s: add a check that catches %s, or list "
                    "%s with the reason no picture can tell %s from the solution\n",
                    stage.id.c_str(), unlisted.size(), unlisted.size() == 1 ? "" : "s",
                    p.knownFile.c_str(), unlisted.size() == 1 ? "it" : "them",
                    unlisted.size() == 1 ? "it" : "them", unlisted.size() == 1 ? "it" : "them");
    return unlisted.empty() ? 0 : 1;
}

int cmdMutants(const MutantsOptions& o) {
    // Everything that can be wrong with the input is found before anything is
    // written: bad input leaves no partial output.
    if (o.stage.empty()) throw Error("--stage is required (a stage id, or all)");
    if (o.outDir.empty()) throw Error("--out is required");
    if (o.max < 0) throw Error("--max must be 0 (every mutant) or more");
    if (o.jobs < 1 || o.jobs > 64) throw Error("--jobs must be between 1 and 64");
    if (!(o.timeoutSeconds > 0.0) || o.timeoutSeconds > 3600.0)
        throw Error("--timeout must be between 0 and 3600 seconds");
    std::error_code ec;
    if (fs::exists(o.outDir, ec) && !fs::is_directory(o.outDir, ec))
        throw Error("--out '" + o.outDir + "': not a folder");
    if (!o.knownDir.empty() && !fs::is_directory(o.knownDir, ec))
        throw Error("--known '" + o.knownDir + "': no such folder");
    std::vector<const StageInfo*> stages;
    if (o.stage == "all") {
        for (const StageInfo& s : allStages()) stages.push_back(&s);
    } else {
        stages.push_back(&findStage(o.stage));
    }
    std::vector<StagePlan> plans;
    for (const StageInfo* s : stages) plans.push_back(planStage(*s, o));

    int code = 0;
    StageOutcome total;
    for (const StagePlan& p : plans) {
        const fs::path out =
            o.stage == "all" ? fs::path(o.outDir) / p.stage->id : fs::path(o.outDir);
        const int c = runStage(p, out, o, total);
        if (c == 130) return c;
        code = std::max(code, c);
    }
    if (plans.size() > 1) {
        std::size_t graded = 0;
        for (const StagePlan& p : plans) graded += p.mutants.size();
        std::printf("all stages: caught %zu of %zu; %zu survived\n", total.caught, graded,
                    total.survivors.size());
    }
    return code;
}

}  // namespace

Command mutantsCommand() {
    return {"mutants",
            "mutation testing for instructors: grade single-token mutants of a stage's solution "
            "and list those the checks miss",
            [](CLI::App& cmd) {
                auto o = std::make_shared<MutantsOptions>();
                cmd.add_option("--stage", o->stage, "the stage (01, 3, f2, ...) or all");
                cmd.add_option("--out", o->outDir,
                               "folder for mutants.md, survivors.txt and the grading run (with "
                               "--stage all: one subfolder per stage)");
                cmd.add_option("--max", o->max, "grade a sample of at most this many (0: all)")
                    ->capture_default_str();
                cmd.add_option("--seed", o->seed, "seed of the sample and of the seeded views")
                    ->capture_default_str();
                cmd.add_option("--jobs", o->jobs, "mutants graded at once")->capture_default_str();
                cmd.add_option("--timeout", o->timeoutSeconds, "seconds per mutant")
                    ->capture_default_str();
                cmd.add_option("--known", o->knownDir,
                               "folder of <stage>.txt files listing the explained survivors "
                               "(tests/mutants); an unlisted survivor makes the exit code 1");
                return std::function<int()>([=] { return cmdMutants(*o); });
            }};
}

}  // namespace raylab
