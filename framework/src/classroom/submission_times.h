#pragma once
// When each student submitted each stage, for a course's late policy
// (`raylab grade --submitted SOURCE`):
//  - a CSV with the columns `student`, `submitted` (ISO 8601 with a zone:
//    2026-12-11T08:30:00Z) and optionally `stage` (a row without one is the
//    time of every stage of that student);
//  - `mtime`: the newest modification time of the files in the student's
//    stage folder (as an LMS download or a copy that keeps times leaves it).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

class SubmissionTimes {
public:
    // SOURCE: a CSV file or "mtime" (then SUBMISSIONS is the class folder).
    // Throws Error naming the file and line.
    static SubmissionTimes read(const std::string& source,
                                const std::filesystem::path& submissions);
    std::optional<std::int64_t> of(const std::string& student, const std::string& stage) const;
    std::string source() const { return source_; }
    // The students it has times for (a CSV's; mtime: the class's folders).
    std::vector<std::string> students() const;

private:
    std::string source_;
    std::filesystem::path submissions_;                                  // mtime
    std::map<std::pair<std::string, std::string>, std::int64_t> times_;  // (student, stage or "")
};

}  // namespace raylab
