// Blackboard Learn's Grade Center upload (grade_report.h).
#include "grade_report.h"

#include "error.h"
#include "report_text.h"

namespace raylab {

using namespace report;

namespace {

// Blackboard wants every field of a comma-delimited upload in quotes.
std::string quoted(const std::string& raw) {
    const std::string field = csvField(raw);
    return !field.empty() && field.front() == '"' ? field : "\"" + field + "\"";
}

}  // namespace

std::string blackboardCsv(const ClassResult& r, const GradebookColumns& columns) {
    const std::string eol = "\r\n";
    std::string out = "\"Last Name\",\"First Name\",\"Username\",\"Student ID\"";
    for (const std::string& id : r.stages) {
        // A column's id (" |1234", as the Grade Center's download writes it)
        // updates that column; a name without one makes a new column.
        auto known = columns.ids.find(id);
        out +=
            "," +
            quoted(columns.prefix + id +
                   (known == columns.ids.end() ? "" : " [Total Pts: 100 Score] |" + known->second));
    }
    out += eol;
    return out + gradebookRows(
                     r,
                     // The Grade Center matches by username only.
                     [](const RosterEntry& e) { return !e.loginId.empty(); },
                     [&](const StudentResult& st) {
                         const RosterEntry& e = st.roster;
                         const auto [last, first] =
                             lastAndFirst(e.fullName.empty() ? st.name : e.fullName);
                         std::string row = quoted(last) + "," + quoted(first) + "," +
                                           quoted(e.loginId) + "," + quoted(e.id);
                         for (const std::string& id : r.stages)
                             row += "," + quoted(gradebookCell(st, id));
                         return row;
                     },
                     "--lms blackboard: no student has a username the Grade Center can match "
                     "(the roster's login_id column)");
}

}  // namespace raylab
