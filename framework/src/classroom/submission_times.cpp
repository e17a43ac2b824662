#include "submission_times.h"

#include "course_file.h"
#include "csv_text.h"
#include "error.h"
#include "paths.h"
#include "stage_catalog.h"

#include <chrono>

namespace raylab {

namespace fs = std::filesystem;

SubmissionTimes SubmissionTimes::read(const std::string& source, const fs::path& submissions) {
    SubmissionTimes t;
    t.source_ = source;
    if (source == "mtime") {
        if (submissions.empty())
            throw Error("--submitted mtime needs --submissions (the folders' times)");
        t.submissions_ = submissions;
        return t;
    }
    const std::string shown = "--submitted " + source;
    std::error_code ec;
    if (!fs::is_regular_file(source, ec))
        throw Error(shown + ": no such file (give a CSV of student,submitted[,stage] or mtime)");
    const CsvTable table = parseCsv(readTextFile(source), shown);
    const int student = table.column("student"), submitted = table.column("submitted"),
              stage = table.column("stage");
    if (student < 0 || submitted < 0)
        throw Error(shown + ": needs the columns student and submitted (and optionally stage)");
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const auto& row = table.rows[i];
        const std::string at = shown + ": line " + std::to_string(table.lines[i]);
        std::string id;
        if (stage >= 0 && !row[std::size_t(stage)].empty()) {
            try {
                id = findStage(row[std::size_t(stage)]).id;
            } catch (const Error& e) { throw Error(at + ": " + e.what()); }
        }
        const std::int64_t when = parseIsoTime(row[std::size_t(submitted)], at);
        if (!t.times_.emplace(std::make_pair(row[std::size_t(student)], id), when).second)
            throw Error(at + ": " + row[std::size_t(student)] + (id.empty() ? "" : " " + id) +
                        " is listed twice");
    }
    return t;
}

std::optional<std::int64_t> SubmissionTimes::of(const std::string& student,
                                                const std::string& stage) const {
    if (!submissions_.empty()) {
        const fs::path dir = submissions_ / student / stage;
        std::error_code ec;
        if (!fs::is_directory(dir, ec)) return std::nullopt;
        std::optional<fs::file_time_type> newest;
        for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
            if (it->is_regular_file(ec)) {
                const fs::file_time_type m = it->last_write_time(ec);
                if (!ec && (!newest || m > *newest)) newest = m;
            }
        if (!newest) return std::nullopt;
        const auto system = std::chrono::time_point_cast<std::chrono::seconds>(
            *newest - fs::file_time_type::clock::now() + std::chrono::system_clock::now());
        return std::int64_t(system.time_since_epoch().count());
    }
    auto it = times_.find({student, stage});
    if (it == times_.end()) it = times_.find({student, ""});
    if (it == times_.end()) return std::nullopt;
    return it->second;
}

std::vector<std::string> SubmissionTimes::students() const {
    std::vector<std::string> out;
    if (!submissions_.empty()) {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(submissions_, ec))
            if (e.is_directory(ec)) out.push_back(e.path().filename().string());
        return out;
    }
    for (const auto& [key, when] : times_)
        if (out.empty() || out.back() != key.first) out.push_back(key.first);
    return out;
}

}  // namespace raylab
