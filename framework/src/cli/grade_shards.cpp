#include "grade_shards.h"

#include "atomic_file.h"
#include "commands.h"
#include "course_file.h"
#include "error.h"
#include "grade_stage.h"
#include "json_reader.h"
#include "paths.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace raylab {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr int kMaxShards = 10000;
constexpr const char* kShardFile = "shard.json";

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

namespace {

json classResultJson(const ClassResult& result) {
    json doc = {{"seed", result.seed},
                {"stages", result.stages},
                {"machine", result.machine},
                {"seconds", result.seconds},
                {"anonymised", result.anonymised},
                {"course_digest", result.courseDigest},
                {"students", json::array()}};
    for (const StudentResult& st : result.students) {
        json stages = json::array();
        for (const StageResult& r : st.stages) stages.push_back(json::parse(stageResultToJson(r)));
        doc["students"].push_back({{"name", st.name}, {"stages", stages}});
    }
    return doc;
}

ClassResult classResultFrom(const json& doc) {
    ClassResult result;
    result.seed = doc.at("seed").get<unsigned>();
    result.stages = doc.at("stages").get<std::vector<std::string>>();
    result.machine = doc.at("machine").get<std::string>();
    result.seconds = doc.at("seconds").get<double>();
    result.anonymised = doc.value("anonymised", false);
    result.courseDigest = doc.value("course_digest", "");
    for (const json& st : doc.at("students")) {
        StudentResult student;
        student.name = st.at("name").get<std::string>();
        for (const json& r : st.at("stages"))
            student.stages.push_back(stageResultFromJson(r.dump()));
        result.students.push_back(std::move(student));
    }
    return result;
}

constexpr const char* kClassFile = "class.json";

}  // namespace

void writeShardFile(const ClassResult& result, const Shard& shard, const fs::path& outDir) {
    json doc = classResultJson(result);
    doc["shard"] = shard.index;
    doc["of"] = shard.count;
    writeTextFileAtomic(outDir / kShardFile, doc.dump(1) + "\n");
}

std::string fileDigest(const std::string& file) {
    if (file.empty()) return "";
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the text: a change, not an attack
    for (char c : readTextFile(file)) h = (h ^ std::uint8_t(c)) * 1099511628211ull;
    char out[24];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
    return out;
}

void writeClassFile(const ClassResult& result, const FinishSettings& settings,
                    const fs::path& outDir) {
    json doc = classResultJson(result);
    doc["finish"] = {{"course", settings.course},
                     {"roster", settings.roster},
                     {"roster_digest", fileDigest(settings.roster)},
                     {"submitted", settings.submitted},
                     {"lms", settings.lms}};
    writeTextFileAtomic(outDir / kClassFile, doc.dump(1) + "\n");
}

ClassResult readClassFile(const fs::path& outDir, FinishSettings* settings) {
    const fs::path file = outDir / kClassFile;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw Error(outDir.string() + ": no " + kClassFile +
                    " (not the output of a finished `raylab grade` run)");
    try {
        const json doc = json::parse(readTextFile(file));
        if (settings) {
            const json f = doc.value("finish", json::object());
            settings->course = f.value("course", "");
            settings->roster = f.value("roster", "");
            settings->rosterDigest = f.value("roster_digest", "");
            settings->submitted = f.value("submitted", "");
            settings->lms = f.value("lms", "");
        }
        return classResultFrom(doc);
    } catch (const json::exception& e) {
        throw Error(file.string() + ": not a class file this raylab wrote (" + e.what() + ")");
    }
}

namespace {

struct ShardFile {
    fs::path dir;
    int index = 0, count = 0;
    ClassResult result;
};

ShardFile readShardFile(const fs::path& dir) {
    const fs::path file = dir / kShardFile;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw Error(dir.string() + ": no " + kShardFile +
                    " (not the output of `raylab grade --shard K/N`, or that run did not finish)");
    ShardFile s;
    s.dir = dir;
    try {
        const json doc = json::parse(readTextFile(file));
        s.index = doc.at("shard").get<int>();
        s.count = doc.at("of").get<int>();
        s.result = classResultFrom(doc);
    } catch (const json::exception& e) {
        throw Error(file.string() + ": not a shard file this raylab wrote (" + e.what() + ")");
    }
    return s;
}

}  // namespace

int cmdGradeMerge(const std::vector<std::string>& args, const GradeOptions& options) {
    if (args.size() < 2)
        throw Error(
            "--merge OUT SHARD_DIR...: give the output folder and at least one shard folder");
    const fs::path out = args[0];
    // What finishing needs is there before anything is written.
    if (!options.course.empty() && readCourseFile(options.course).late && options.submitted.empty())
        throw Error("--merge --course " + options.course +
                    " has a late policy: give --submitted CSV (student,submitted[,stage])");
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
    for (const char* own : {"students", "reference", "report.html", "summary.csv", "junit.xml",
                            "class.json", "canvas.csv"})
        fs::remove_all(out / own, ec);
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
    std::printf("merged; report: %s\n",
                fs::absolute(out / "report.html").lexically_normal().c_str());
    return 0;
}

}  // namespace raylab
