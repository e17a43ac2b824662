#include "class_file.h"

#include "atomic_file.h"
#include "error.h"
#include "grade_stage.h"
#include "paths.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>

namespace raylab {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr const char* kShardFile = "shard.json";

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
        json regrades = json::array();
        for (const Regrade& g : st.regrades) {
            json changes = json::array();
            for (const RegradeChange& c : g.changes)
                changes.push_back({{"stage", c.stage}, {"before", c.before}, {"after", c.after}});
            regrades.push_back({{"when", g.when}, {"reason", g.reason}, {"changes", changes}});
        }
        doc["students"].push_back({{"name", st.name}, {"stages", stages}, {"regrades", regrades}});
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
        for (const json& g : st.value("regrades", json::array())) {
            Regrade regrade{g.at("when").get<std::string>(), g.at("reason").get<std::string>(), {}};
            for (const json& c : g.at("changes"))
                regrade.changes.push_back({c.at("stage").get<std::string>(),
                                           c.at("before").get<std::string>(),
                                           c.at("after").get<std::string>()});
            student.regrades.push_back(std::move(regrade));
        }
        for (const json& r : st.at("stages"))
            student.stages.push_back(stageResultFromJson(r.dump()));
        result.students.push_back(std::move(student));
    }
    return result;
}

constexpr const char* kClassFile = "class.json";

}  // namespace

void writeShardFile(const ClassResult& result, int index, int count, const fs::path& outDir) {
    json doc = classResultJson(result);
    doc["shard"] = index;
    doc["of"] = count;
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

}  // namespace raylab
