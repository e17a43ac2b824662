// Canvas's gradebook import CSV (grade_report.h).
#include "grade_report.h"

#include "atomic_file.h"
#include "error.h"
#include "report_text.h"

namespace raylab {

using namespace report;
namespace fs = std::filesystem;

std::string canvasCsv(const ClassResult& r, const std::string& prefix) {
    const std::string eol = "\r\n";
    std::string out = "Student,ID,SIS User ID,SIS Login ID,Section";
    for (const std::string& id : r.stages) out += "," + csvField(prefix + id);
    out += eol + "Points Possible,,,,";
    for (std::size_t i = 0; i < r.stages.size(); ++i) out += ",100";
    out += eol;
    int rows = 0;
    for (const StudentResult& st : r.students) {
        const RosterEntry& e = st.roster;
        if (e.canvasId.empty() && e.id.empty() && e.loginId.empty()) continue;
        out += csvField(e.fullName.empty() ? st.name : e.fullName) + "," + csvField(e.canvasId) +
               "," + csvField(e.id) + "," + csvField(e.loginId) + "," + csvField(e.section);
        for (const std::string& id : r.stages) {
            const StageResult* s = findStage(st, id);
            out += ",";
            if (s && s->status != "not submitted") out += num(s->score);
        }
        out += eol;
        ++rows;
    }
    if (rows == 0)
        throw Error("--lms canvas: no student has an id Canvas can match (the roster's "
                    "canvas_id, id or login_id column)");
    return out;
}

void writeCanvasCsv(const ClassResult& result, const fs::path& file, const std::string& prefix) {
    writeTextFileAtomic(file, canvasCsv(result, prefix));
}

}  // namespace raylab
