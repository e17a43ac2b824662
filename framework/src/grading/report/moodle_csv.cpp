// Moodle's grade import CSV (grade_report.h).
#include "grade_report.h"

#include "error.h"
#include "report_text.h"

namespace raylab {

using namespace report;

std::string moodleCsv(const ClassResult& r, const GradebookColumns& columns) {
    const std::string eol = "\r\n";
    // Moodle's import asks which column identifies the user ("Map from") and
    // as what ("Map to": ID number, email address or username), then which
    // grade item each other column fills (or a new one of that name).
    std::string out = "First name,Last name,ID number,Email address,Username";
    for (const std::string& id : r.stages) out += "," + csvField(columns.prefix + id);
    out += eol;
    return out + gradebookRows(
                     r,
                     [](const RosterEntry& e) {
                         return !e.id.empty() || !e.email.empty() || !e.loginId.empty();
                     },
                     [&](const StudentResult& st) {
                         const RosterEntry& e = st.roster;
                         const auto [last, first] =
                             lastAndFirst(e.fullName.empty() ? st.name : e.fullName);
                         std::string row = csvField(first) + "," + csvField(last) + "," +
                                           csvField(e.id) + "," + csvField(e.email) + "," +
                                           csvField(e.loginId);
                         for (const std::string& id : r.stages) row += "," + gradebookCell(st, id);
                         return row;
                     },
                     "--lms moodle: no student has an id Moodle can match (the roster's id, "
                     "email or login_id column)");
}

}  // namespace raylab
