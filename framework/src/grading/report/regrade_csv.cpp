// The regrade log (grade_report.h).
#include "grade_report.h"

#include "report_text.h"

namespace raylab {

using namespace report;

std::string regradeCsv(const ClassResult& r) {
    const std::string eol = "\r\n";
    std::string out = "when,student,reason,stage,before,after" + eol;
    for (const StudentResult& st : r.students)
        for (const Regrade& g : st.regrades) {
            const std::string head =
                csvField(g.when) + "," + csvField(st.name) + "," + csvField(g.reason) + ",";
            if (g.changes.empty()) out += head + ",," + eol;
            for (const RegradeChange& c : g.changes)
                out += head + csvField(c.stage) + "," + csvField(c.before) + "," +
                       csvField(c.after) + eol;
        }
    return out;
}

}  // namespace raylab
