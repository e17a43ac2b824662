#pragma once
// A stage's lab folder at a level, as `raylab-labgen` writes labs/ (the
// guided level) and `raylab handout --level open` hands it out: the shader
// files (lab_files.h) and the guide.
//
// One guide source serves both levels: solution/<id>/guide.md. Text between
// "<!-- guided -->" and "<!-- /guided -->" lines is the guided level's
// only, between "<!-- open -->" and "<!-- /open -->" the open level's; the
// rest, every heading included, is shared, so both guides have one outline.
#include "lab_markers.h"
#include "stage_catalog.h"
#include "stage_grading.h"

#include <filesystem>
#include <map>
#include <string>

namespace raylab {

// What a guide says that needs the course's solution or its reference
// tracer (`run --solution`, `render --reference`, `demo`), between
// "<!-- with-solution -->" and "<!-- /with-solution -->": kept in the
// template's labs, left out of a student repository (`raylab student-repo`),
// whose build has neither. What it says there instead, between
// "<!-- without-solution -->" and "<!-- /without-solution -->": the other
// way round.
enum class SolutionText { Keep, LeaveOut };

// SOURCE (a guide.md, FILE in messages) at LEVEL, the level markers and the
// with-solution markers removed (with SOLUTION LeaveOut, what they enclose
// too). Throws Error("FILE:LINE: ...") for an unclosed or nested section or
// a heading inside one.
std::string guideAtLevel(const std::string& source, Level level, const std::string& file,
                         SolutionText solution = SolutionText::Keep);

// The hand-made files of the lab folder DIR (labs/<id>/: pictures, not the
// shader files or README.md) as a lab folder at LEVEL holds them: its name
// there -> the file. "NAME-open.png" is the open level's NAME.png (the
// untouched open lab looks other than the guided one), in place of the
// guided one there and left out at the guided level.
std::map<std::string, std::filesystem::path> labPictures(const std::filesystem::path& dir,
                                                         Level level);

// STAGE's guide at LEVEL, its "How you are graded" from GRADING.
std::string stageGuide(const StageInfo& stage, Level level, const StageGrading& grading,
                       SolutionText solution = SolutionText::Keep);

// Every generated file of STAGE's lab folder at LEVEL: name -> text (the
// shader files and README.md, the guide with the stage's own grading and
// its with-solution or without-solution text; none for a stage without a
// guide.md yet).
std::map<std::string, std::string> labFolderFiles(const StageInfo& stage, Level level,
                                                  SolutionText solution = SolutionText::Keep);

}  // namespace raylab

namespace raylab {

// The labs as the course hands them out, at its level: what grading renders
// as "the lab as handed out" (a picture equal to it earns nothing), fills a
// submission's missing files from, and lays loose uploaded files over.
// labs/ at the guided level; at the open level the open labs' shader files,
// written once to a temporary folder by the process that sets the level
// (removed when it exits) and read by its child processes.
//
// The level is the environment's RAYLAB_LEVEL ("guided" when unset), so that
// the child processes a grading command starts grade at its level too:
// setHandedOutLevel sets it for this process and its children.
void setHandedOutLevel(Level level);
Level handedOutLevel();  // throws Error for an unknown RAYLAB_LEVEL
std::filesystem::path handedOutLabRoot();

}  // namespace raylab
