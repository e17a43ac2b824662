// The class summary as CSV (grade_report.h).
#include "grade_report.h"

#include "atomic_file.h"
#include "report_text.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

using namespace report;
namespace fs = std::filesystem;

// ---------------------------------------------------------------- CSV

std::string summaryCsv(const ClassResult& r) {
    const std::string eol = "\r\n";
    std::string out = "student,id";
    for (const std::string& id : r.stages) out += "," + csvField(id);
    out += ",total,max,notes" + eol;
    for (const StudentResult& st : r.students) {
        out += csvField(st.name) + "," + csvField(st.roster.id);
        std::string notes;
        auto note = [&notes](const std::string& n) { notes += (notes.empty() ? "" : "; ") + n; };
        if (!st.hasFolder) note("no submission folder");
        for (const std::string& id : r.stages) {
            const StageResult* s = findStage(st, id);
            out += ",";
            if (!s) {
                note(id + ": no result");
                continue;
            }
            // Not submitted is no score at all (an LMS tells it from a 0).
            if (s->excused) out += "EX";
            else if (s->status != "not submitted") out += num(s->score);
            if (s->excused) note(id + ": excused (" + s->excuseNote + ")");
            else if (!isGraded(*s) && st.hasFolder) note(id + ": " + statusWord(*s));
            if (!s->lateNote.empty()) note(id + ": " + s->lateNote);
        }
        out += "," + num(st.score()) + "," + num(st.maxScore()) + "," + csvField(notes) + eol;
    }
    return out;
}

void writeSummaryCsv(const ClassResult& result, const fs::path& file) {
    writeTextFileAtomic(file, summaryCsv(result));
}

}  // namespace raylab
