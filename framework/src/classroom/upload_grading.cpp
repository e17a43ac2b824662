#include "upload_grading.h"
#include "lab_folder.h"

#include "error.h"
#include "grade_class.h"
#include "stage_list.h"

namespace raylab {

namespace fs = std::filesystem;

std::vector<std::string> stageList(const std::string& list) { return parseStageIds(list); }

std::string UploadGrade::shown(std::string text) const {
    if (workPrefix.empty()) return text;
    for (std::size_t at; (at = text.find(workPrefix)) != std::string::npos;)
        text.erase(at, workPrefix.size());
    return text;
}

UploadGrade gradeUpload(const fs::path& uploaded, const fs::path& work,
                        const UploadGradeOptions& o) {
    UploadGrade r;
    std::error_code ec;
    fs::remove_all(work, ec);
    // Loose files, missing files and "the lab as handed out" at the course's level.
    setHandedOutLevel(o.level);
    try {
        r.layout =
            layOutSubmission(uploaded, o.stages, work / "class" / "student", work / "unpacked");
    } catch (const fs::filesystem_error& e) {  // an upload that cannot be read or copied
        r.layout.problem = "the submission cannot be read: " + std::string(e.what());
    }
    if (!r.layout.problem.empty()) return r;

    GradeOptions g;
    g.submissions = (work / "class").string();
    g.outDir = (work / "out").string();
    for (const std::string& s : o.stages) g.stages += (g.stages.empty() ? "" : ",") + s;
    g.jobs = 1;  // one stage at a time: the memory of one child at most
    g.seed = o.seed;
    g.timeoutSeconds = o.timeoutSeconds;
    g.memoryMb = o.memoryMb;
    std::optional<ClassResult> graded = gradeClass(g);
    if (!graded || graded->students.empty()) throw Error("grading was interrupted");
    r.student = graded->students.front();
    r.outDir = work / "out";
    r.workPrefix = (work / "class" / "student").string() + "/";
    return r;
}

}  // namespace raylab
