#pragma once
// Grading one student's upload, as the course engines' graders do (`raylab
// prairielearn`, `raylab gradescope`): the upload laid out like labs/
// (submission_layout.h), graded by the class grader (gradeClass: every stage
// in its own child process), and the messages made to name the student's own
// files ("01-raycast/intersect_sphere.glsl:24") rather than the grader's
// working copy.
#include "grade_result.h"
#include "lab_markers.h"
#include "submission_layout.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

struct UploadGradeOptions {
    std::vector<std::string> stages;  // stage ids, as findStage() gives them
    unsigned seed = 0;
    double timeoutSeconds = 60.0;  // per stage
    long memoryMb = 2048;          // per stage (address space)
    Level level = Level::Guided;   // of the labs handed out (lab_folder.h)
};

struct UploadGrade {
    SubmissionLayout layout;                    // layout.problem set: not gradable
    std::optional<StudentResult> student;       // set when graded
    std::filesystem::path outDir;               // the grader's output (heat maps under it)
    std::string workPrefix;                     // the working copy's path, as messages show it
    std::string shown(std::string text) const;  // TEXT without workPrefix
};

// Grades UPLOADED in WORK (emptied first). An upload that cannot be read is
// not gradable (layout.problem says why), never an exception. Throws Error
// when grading itself fails or is interrupted.
UploadGrade gradeUpload(const std::filesystem::path& uploaded, const std::filesystem::path& work,
                        const UploadGradeOptions& options);

// "01,03-shadows" -> {"01-raycast", "03-shadows"}; ranges as `handout` takes them
// (stage_list.h). Throws Error on an unknown stage.
std::vector<std::string> stageList(const std::string& list);

}  // namespace raylab
