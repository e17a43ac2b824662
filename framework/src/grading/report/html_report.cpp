// Writing the HTML report (grade_report.h): the class's page and a page per
// student beside their results.
#include "grade_report.h"

#include "atomic_file.h"
#include "error.h"

namespace raylab {

namespace fs = std::filesystem;

void writeHtmlReport(const ClassResult& result, const fs::path& outDir,
                     const ClassPageOptions& options) {
    // The report goes into a results folder that grading made; a missing one
    // is a wrong path, and creating it would leave students/ there unasked.
    if (!fs::is_directory(outDir))
        throw Error(outDir.string() + ": cannot write the report there (no such folder)");
    for (const StudentResult& st : result.students) {
        if (!st.hasFolder) continue;  // only in the roster: nothing graded, no page
        const fs::path folder = outDir / "students" / st.name;
        std::error_code ec;
        fs::create_directories(folder, ec);
        if (ec) throw Error(folder.string() + ": cannot create the folder (" + ec.message() + ")");
        writeTextFileAtomic(folder / "report.html", htmlStudentPage(result, st));
    }
    writeTextFileAtomic(outDir / "report.html", htmlClassPage(result, options));
}

}  // namespace raylab
