#pragma once
// The shader files of one stage's lab, generated from solution/: what
// `raylab-labgen` writes to labs/<stage>/ (lab form) or to a solved copy, and
// what `raylab mutants` starts each mutant from. One place decides which
// files a lab holds, so a mutant is graded exactly as a student's lab is.
#include "lab_markers.h"
#include "stage_catalog.h"

#include <filesystem>
#include <map>
#include <string>

namespace raylab {

struct LabFile {
    std::filesystem::path source;  // the marked file under solution/
    bool own = false;              // a file of this stage's own folder (its TODOs)
};

// File name -> where it comes from, for every shader file the stage's
// programs include, except the framework's own (framework/shaders/).
std::map<std::string, LabFile> labFileSources(const StageInfo& stage);

// File name -> generated text: the stage's own files in FORMOFOWNFILES (a lab
// at LEVEL, or solved), the earlier stages' files solved.
std::map<std::string, std::string> labFiles(const StageInfo& stage, MarkedForm formOfOwnFiles,
                                            Level level = Level::Guided);

}  // namespace raylab
