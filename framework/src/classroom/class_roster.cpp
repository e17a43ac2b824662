#include "class_roster.h"

#include "csv_text.h"
#include "error.h"
#include "paths.h"

namespace raylab {

std::map<std::string, RosterEntry> readRoster(const std::filesystem::path& file) {
    const std::string shown = "--roster " + displayPath(file);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw Error(shown + ": no such file");
    const CsvTable t = parseCsv(readTextFile(file), shown);
    const int student = t.column("student");
    if (student < 0)
        throw Error(shown + ": no 'student' column (the submission folder's name; optional: id, "
                            "name, canvas_id, login_id, section, email)");
    auto cell = [&](const std::vector<std::string>& row, const char* name) {
        const int c = t.column(name);
        return c < 0 ? std::string() : row[std::size_t(c)];
    };
    std::map<std::string, RosterEntry> roster;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const std::vector<std::string>& row = t.rows[i];
        const std::string name = row[std::size_t(student)];
        const std::string at = shown + ": line " + std::to_string(t.lines[i]);
        if (name.empty()) throw Error(at + ": the student column is empty");
        RosterEntry e{cell(row, "id"),       cell(row, "name"),    cell(row, "canvas_id"),
                      cell(row, "login_id"), cell(row, "section"), cell(row, "email")};
        if (!roster.emplace(name, e).second) throw Error(at + ": " + name + " is listed twice");
    }
    return roster;
}

}  // namespace raylab
