#pragma once
// What students upload to a course's grading engine, made into a folder laid
// out like labs/ (one folder per stage) that `raylab grade` takes:
//  - a whole labs/ folder, or some of its stage folders;
//  - the same inside one extra top folder (a zip of the folder);
//  - loose shader files of one stage: they replace the lab's own files of
//    that stage (labs/<stage>/), so students upload only what they edited;
//  - any of these as one zip file (PrairieLearn stores an uploaded zip as a
//    file; Gradescope unpacks it itself): unpacked first (zip_unpack.h).
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct SubmissionLayout {
    bool empty = false;              // nothing was uploaded
    std::string problem;             // why it cannot be graded ("" when it can)
    std::vector<std::string> notes;  // files left out, and why
};

// Writes the submission in UPLOADED as LABROOT (a new folder) for STAGES
// (the stages this assignment grades). A zip is unpacked into SCRATCH (a new
// folder, outside LABROOT's parent).
SubmissionLayout layOutSubmission(const std::filesystem::path& uploaded,
                                  const std::vector<std::string>& stages,
                                  const std::filesystem::path& labRoot,
                                  const std::filesystem::path& scratch);

}  // namespace raylab
