#pragma once
// What a grading run keeps in its output folder besides the reports, so that
// later steps can finish the class without grading it again:
//  - OUT/class.json: every result of a whole run as graded (before a late
//    policy or a roster) and the settings that finished it: what `raylab
//    grade --only NAME` regrades one student into;
//  - OUT/shard.json: a share's place (K of N) and its students' results,
//    what `raylab grade --merge` puts together (grade_shards.h).
#include "grade_result.h"

#include <filesystem>
#include <string>

namespace raylab {

// What finished the reports (the options of the course's workflow), kept in
// class.json so that --only finishes the class the same way.
struct FinishSettings {
    std::string course, courseDigest, roster, rosterDigest, submitted, lms;
};
void writeClassFile(const ClassResult& result, const FinishSettings& settings,
                    const std::filesystem::path& outDir);
ClassResult readClassFile(const std::filesystem::path& outDir,
                          FinishSettings* settings = nullptr);  // throws Error

// A digest of FILE's text ("" for no file): what tells a changed course file.
std::string fileDigest(const std::string& file);

struct ShardFile {
    std::filesystem::path dir;
    int index = 0, count = 0;  // share INDEX of COUNT
    ClassResult result;
};
void writeShardFile(const ClassResult& result, int index, int count,
                    const std::filesystem::path& outDir);
ShardFile readShardFile(const std::filesystem::path& dir);  // throws Error

}  // namespace raylab
