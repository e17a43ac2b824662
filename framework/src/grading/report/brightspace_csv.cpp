// Brightspace (D2L)'s grades import CSV (grade_report.h).
#include "grade_report.h"

#include "error.h"
#include "report_text.h"

namespace raylab {

using namespace report;

std::string brightspaceCsv(const ClassResult& r, const GradebookColumns& columns) {
    const std::string eol = "\r\n";
    // OrgDefinedId and Username first, each grade item's column named
    // "<item> Points Grade", and the End-of-Line Indicator last. The '#'
    // before the ids and as the indicator is Brightspace's own export's: it
    // keeps a spreadsheet from turning "00246" into 246, and marks each
    // record's end so that an empty last grade is not read as a short line.
    std::string out = "OrgDefinedId,Username";
    for (const std::string& id : r.stages)
        out += "," + csvField(columns.prefix + id + " Points Grade");
    out += ",End-of-Line Indicator" + eol;
    return out + gradebookRows(
                     r, [](const RosterEntry& e) { return !e.id.empty() || !e.loginId.empty(); },
                     [&](const StudentResult& st) {
                         const RosterEntry& e = st.roster;
                         std::string row = (e.id.empty() ? "" : csvField("#" + e.id)) + "," +
                                           (e.loginId.empty() ? "" : csvField("#" + e.loginId));
                         for (const std::string& id : r.stages) row += "," + gradebookCell(st, id);
                         return row + ",#";
                     },
                     "--lms brightspace: no student has an id Brightspace can match (the "
                     "roster's id as OrgDefinedId, or login_id as Username)");
}

}  // namespace raylab
