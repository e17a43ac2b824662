// Canvas's gradebook import CSV (grade_report.h).
#include "grade_report.h"

#include "atomic_file.h"
#include "error.h"
#include "report_text.h"

namespace raylab {

using namespace report;
namespace fs = std::filesystem;

std::string canvasCsv(const ClassResult& r, const GradebookColumns& columns) {
    const std::string eol = "\r\n";
    std::string out = "Student,ID,SIS User ID,SIS Login ID,Section";
    for (const std::string& id : r.stages) {
        // "Name (12345)" is how Canvas's own export names an assignment's
        // column; with the id Canvas updates that assignment whatever its name.
        auto known = columns.ids.find(id);
        out += "," + csvField(columns.prefix + id +
                              (known == columns.ids.end() ? "" : " (" + known->second + ")"));
    }
    out += eol + "Points Possible,,,,";
    for (std::size_t i = 0; i < r.stages.size(); ++i) out += ",100";
    out += eol;
    return out + gradebookRows(
                     r,
                     [](const RosterEntry& e) {
                         return !e.canvasId.empty() || !e.id.empty() || !e.loginId.empty();
                     },
                     [&](const StudentResult& st) {
                         const RosterEntry& e = st.roster;
                         std::string row = csvField(e.fullName.empty() ? st.name : e.fullName) +
                                           "," + csvField(e.canvasId) + "," + csvField(e.id) + "," +
                                           csvField(e.loginId) + "," + csvField(e.section);
                         for (const std::string& id : r.stages)
                             row += "," + gradebookCell(st, id, "EX");
                         return row;
                     },
                     "--lms canvas: no student has an id Canvas can match (the roster's "
                     "canvas_id, id or login_id column)");
}

}  // namespace raylab
