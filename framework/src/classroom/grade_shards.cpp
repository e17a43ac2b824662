#include "grade_shards.h"

#include "class_file.h"
#include "class_reports.h"
#include "class_roster.h"
#include "course_file.h"
#include "error.h"
#include "grade_class.h"
#include "grade_stage.h"
#include "lms_exports.h"
#include "paths.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace raylab {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxShards = 10000;

int wholeNumber(const std::string& text, const std::string& what) {
    if (text.empty() || text.size() > 5 ||
        text.find_first_not_of("0123456789") != std::string::npos)
        throw Error(what);
    return std::stoi(text);
}

}  // namespace

Shard parseShard(const std::string& text) {
    const std::string what =
        "--shard '" + text +
        "': expected K/N, the K-th of N shares (0 <= K < N <= " + std::to_string(kMaxShards) +
        "), e.g. 0/4";
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) throw Error(what);
    Shard s{wholeNumber(text.substr(0, slash), what), wholeNumber(text.substr(slash + 1), what)};
    if (s.count < 1 || s.count > kMaxShards || s.index >= s.count) throw Error(what);
    return s;
}

void mergeShards(const std::vector<std::string>& args, const GradeOptions& options) {
    if (args.size() < 2)
        throw Error(
            "--merge OUT SHARD_DIR...: give the output folder and at least one shard folder");
    const fs::path out = args[0];
    // What finishing needs is there before anything is written.
    if (!options.course.empty() && readCourseFile(options.course).late && options.submitted.empty())
        throw Error("--merge --course " + options.course +
                    " has a late policy: give --submitted CSV (student,submitted[,stage])");
    const std::vector<std::string> lmss = parseLmsList(options.lms);
    if (!lmss.empty() && options.roster.empty())
        throw Error("--merge --lms " + options.lms + " needs --roster FILE");
    if (!options.roster.empty()) checkRosterServes(lmss, readRoster(options.roster));
    std::vector<ShardFile> shards;
    for (std::size_t i = 1; i < args.size(); ++i) shards.push_back(readShardFile(args[i]));

    // Every share exactly once, from one run (same count, seed and stages).
    const ShardFile& first = shards.front();
    std::set<int> seen;
    for (const ShardFile& s : shards) {
        if (s.result.courseDigest != fileDigest(options.course))
            throw Error(s.dir.string() +
                        (s.result.courseDigest.empty()
                             ? " was graded without a course file: merge it without --course"
                             : " was graded with a course file's weights: give --merge the same "
                               "--course (its text unchanged)"));
        if (s.count != first.count || s.result.seed != first.result.seed ||
            s.result.stages != first.result.stages ||
            s.result.anonymised != first.result.anonymised)
            throw Error(s.dir.string() + " is from another run than " + first.dir.string() +
                        " (shares, seed or stages differ)");
        if (!seen.insert(s.index).second)
            throw Error(s.dir.string() + ": share " + std::to_string(s.index) + "/" +
                        std::to_string(s.count) + " is given twice");
    }
    std::string missing;
    for (int k = 0; k < first.count; ++k)
        if (!seen.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    if (!missing.empty())
        throw Error("shares " + missing + " of " + std::to_string(first.count) +
                    " are missing: merging part of a class would report a part as the whole");

    // The class as an unsharded run has it: students in sorted order.
    ClassResult merged;
    merged.seed = first.result.seed;
    merged.stages = first.result.stages;
    merged.machine = first.result.machine;
    merged.anonymised = first.result.anonymised;
    merged.courseDigest = first.result.courseDigest;
    std::map<std::string, const ShardFile*> owner;
    for (const ShardFile& s : shards) {
        merged.seconds = std::max(merged.seconds, s.result.seconds);  // the shares ran side by side
        for (const StudentResult& st : s.result.students) {
            if (!owner.emplace(st.name, &s).second)
                throw Error("student " + st.name + " is in two shares (" +
                            owner[st.name]->dir.string() + ", " + s.dir.string() + ")");
            merged.students.push_back(st);
        }
    }
    std::sort(merged.students.begin(), merged.students.end(),
              [](const StudentResult& a, const StudentResult& b) { return a.name < b.name; });

    // The files: the reference pictures once, every student's folder from its share.
    std::error_code ec;
    for (const std::string& own : classOutputs()) fs::remove_all(out / own, ec);
    fs::create_directories(out, ec);
    if (ec) throw Error("--merge " + out.string() + ": cannot create the folder");
    try {
        fs::copy(first.dir / "reference", out / "reference", fs::copy_options::recursive);
        fs::create_directories(out / "students");
        for (const StudentResult& st : merged.students) {
            const fs::path from = studentFolder(owner[st.name]->dir, st.name);
            if (fs::exists(from, ec))
                fs::copy(from, studentFolder(out, st.name), fs::copy_options::recursive);
        }
    } catch (const fs::filesystem_error& e) {
        throw Error("--merge: cannot copy the shares' files: " + std::string(e.what()));
    }
    std::printf("raylab grade --merge: %zu shares, %zu students x %zu stages\n", shards.size(),
                merged.students.size(), merged.stages.size());
    writeClassFile(merged, {options.course, "", options.roster, "", options.submitted, options.lms},
                   out);
    finishAndReport(merged, options, out);
}

}  // namespace raylab
