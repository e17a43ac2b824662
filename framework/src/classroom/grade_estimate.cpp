#include "grade_estimate.h"

#include "error.h"
#include "grade_class.h"
#include "text_format.h"

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>

namespace raylab {

namespace fs = std::filesystem;

double ClassEstimate::classSeconds() const {
    const double items = double(students * stages) * submittedShare;
    return fixedSeconds + items * itemSeconds / double(std::max(jobs, 1));
}

double ClassEstimate::taskSeconds(int shares, int cpusPerTask) const {
    const double share = std::ceil(double(students) / double(shares));
    return fixedSeconds +
           share * double(stages) * submittedShare * itemSeconds / double(cpusPerTask);
}

double ClassEstimate::uploadSeconds() const {
    // Half a CPU: the same work takes twice as long; the references are
    // rendered for every upload, one stage at a time.
    return 2.0 * (fixedSeconds * double(std::max(jobs, 1)) +
                  double(stages) * submittedShare * itemSeconds);
}

std::vector<std::string> sampleStudents(const std::vector<std::string>& students,
                                        std::size_t sample) {
    if (sample >= students.size()) return students;
    std::vector<std::string> picked;
    for (std::size_t i = 0; i < sample; ++i)
        picked.push_back(
            students[sample == 1 ? students.size() / 2 : i * (students.size() - 1) / (sample - 1)]);
    return picked;
}

ClassEstimate estimateFrom(const std::vector<ItemCost>& items, std::size_t notSubmitted,
                           double sampleSeconds, std::size_t students, std::size_t stages,
                           std::size_t sampled, int jobs) {
    ClassEstimate e;
    e.students = students;
    e.stages = stages;
    e.sampled = sampled;
    e.sampleSeconds = sampleSeconds;
    e.jobs = std::max(jobs, 1);
    double total = 0;
    for (const ItemCost& c : items) {
        // An endless loop is the timeout's cost, once: not what a typical
        // item costs.
        if (c.timedOut) continue;
        total += c.seconds;
        e.itemMaxSeconds = std::max(e.itemMaxSeconds, c.seconds);
        e.peakMb = std::max(e.peakMb, c.peakMb);
    }
    const std::size_t timed = std::size_t(
        std::count_if(items.begin(), items.end(), [](const ItemCost& c) { return !c.timedOut; }));
    e.itemSeconds = timed ? total / double(timed) : 0;
    const std::size_t all = items.size() + notSubmitted;
    e.submittedShare = all ? double(items.size()) / double(all) : 1;
    e.fixedSeconds = std::max(0.0, sampleSeconds - total / double(e.jobs));
    return e;
}

std::string describeEstimate(const ClassEstimate& e, const GradeOptions& g) {
    char line[400];
    std::string out;
    auto add = [&](const char* fmt, auto... args) {
        std::snprintf(line, sizeof line, fmt, args...);
        out += line;
    };
    add("raylab grade --estimate: %zu of %zu students x %zu stage%s graded as a sample in %s\n",
        e.sampled, e.students, e.stages, e.stages == 1 ? "" : "s",
        durationText(e.sampleSeconds).c_str());
    add("  a student-stage: %s on average, %s at most; %s before the first (the references)\n",
        durationText(e.itemSeconds).c_str(), durationText(e.itemMaxSeconds).c_str(),
        durationText(e.fixedSeconds).c_str());
    add("  memory: %.0f MB at most per stage (its limit, --memory-mb: %ld MB%s)\n", e.peakMb,
        g.memoryMb, g.memoryMb == 0 ? ", none" : "");
    add("  the class, %zu students: about %s on this machine with --jobs %d\n", e.students,
        durationText(e.classSeconds()).c_str(), e.jobs);
    out += "  a Slurm array (examples/slurm/, 2 CPUs a task; then --merge):";
    for (int shares : {2, 4, 8, 16})
        if (std::size_t(shares) <= e.students)
            add(" %d tasks %s each;", shares, durationText(e.taskSeconds(shares, 2)).c_str());
    if (!out.empty() && out.back() == ';') out.pop_back();
    add("\n    each task needs about %.0f MB per CPU (sbatch --mem-per-cpu)\n",
        std::ceil(std::max(e.peakMb * 1.5, 256.0)));
    add("  Gradescope (half a CPU, stages one at a time): about %s per upload\n",
        durationText(e.uploadSeconds()).c_str());
    add("  an endless loop costs its --timeout (%.0f s) once%s\n", g.timeoutSeconds,
        g.jobs > 1 ? ", twice when it timed out beside others (then it runs again alone)" : "");
    return out;
}

bool estimateClass(const GradeOptions& g, std::size_t sample) {
    if (sample < 1 || sample > 100) throw Error("--sample must be between 1 and 100");
    const std::vector<std::string> students = studentFolders(g.submissions);
    const std::size_t stages = stagesToGrade(g.stages).size();
    const std::vector<std::string> picked = sampleStudents(students, sample);
    // The sample is graded for real, in a scratch folder of its own.
    std::string pattern = (fs::temp_directory_path() / "raylab-estimate-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw Error("--estimate: cannot make a scratch folder");
    const fs::path scratch = pattern;
    struct Remove {
        fs::path dir;
        ~Remove() {
            std::error_code ec;
            fs::remove_all(dir, ec);
        }
    } remove{scratch};
    try {
        fs::create_directories(scratch / "class");
        for (const std::string& name : picked)
            fs::copy(fs::path(g.submissions) / name, scratch / "class" / name,
                     fs::copy_options::recursive);
    } catch (const fs::filesystem_error& e) {
        throw Error("--estimate: cannot copy the sample (" + e.code().message() + ")");
    }
    GradeOptions s = g;
    s.submissions = (scratch / "class").string();
    s.outDir = (scratch / "out").string();
    s.shard.clear();
    s.only.clear();
    s.anonymise.clear();
    const auto start = std::chrono::steady_clock::now();
    const std::optional<ClassResult> graded = gradeClass(s);
    if (!graded) return false;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<ItemCost> items;
    std::size_t notSubmitted = 0;
    for (const StudentResult& st : graded->students)
        for (const StageResult& r : st.stages) {
            if (r.status == "not submitted") ++notSubmitted;
            else items.push_back({r.seconds, r.peakMb, r.status == "timed out"});
        }
    const ClassEstimate e =
        estimateFrom(items, notSubmitted, seconds, students.size(), stages, picked.size(), g.jobs);
    std::printf("\n%s", describeEstimate(e, g).c_str());
    return true;
}

}  // namespace raylab
