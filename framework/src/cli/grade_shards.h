#pragma once
// Grading a class in shares: `raylab grade --shard K/N` grades every N-th
// student starting at K (of the sorted student folders), so that N jobs of
// a cluster's array (examples/slurm/grade_array.sh) split a class; `raylab
// grade --merge OUT SHARD_DIR...` puts the shares together into the report
// an unsharded run writes (the same scores and files; only timings differ).
#include "grade_result.h"
#include "stage_catalog.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

struct Shard {
    int index = 0;  // K
    int count = 1;  // N; 1: the whole class
};

// "K/N" with 0 <= K < N <= 10000. Throws Error.
Shard parseShard(const std::string& text);

// Whether the student at INDEX of the sorted folders belongs to SHARD.
inline bool inShard(std::size_t index, const Shard& shard) {
    return int(index % std::size_t(shard.count)) == shard.index;
}

// OUT/shard.json: the shard's place and every result of its students.
void writeShardFile(const ClassResult& result, const Shard& shard,
                    const std::filesystem::path& outDir);

// OUT/class.json: every result of a whole run as graded (before a late
// policy or a roster): what `raylab grade --only NAME` regrades one student into.
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

// The class reports in OUT: <student>/results.json, summary.csv, junit.xml,
// report.html (canvas.csv with --lms canvas), and the summary table on
// stdout, after the course's workflow (late policy, roster, the catalogued
// mistakes) is applied to RESULT (cmd_grade.cpp).
struct GradeOptions;
void finishAndReport(ClassResult result, const GradeOptions& options,
                     const std::filesystem::path& outDir);

// Grades the class G describes (its --shard share, if any) into G.outDir's
// students/ and reference/ folders; nullopt when interrupted (Ctrl-C).
// cmdGrade writes the reports; the single-submission graders
// (cmd_prairielearn.cpp) their own results.
std::optional<ClassResult> gradeClass(const GradeOptions& g);

// The stages --stages names ("01-03,f1"); every stage when LIST is empty.
std::vector<const StageInfo*> stagesToGrade(const std::string& list);

// `raylab grade --merge OUT SHARD_DIR...` (OPTIONS: the course's workflow
// options only). Returns the exit code.
int cmdGradeMerge(const std::vector<std::string>& args, const GradeOptions& options);

}  // namespace raylab
