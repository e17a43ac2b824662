#pragma once
// What a handout (`raylab handout`) puts in each stage folder it releases.
// A stage's programs include files of the stages it builds on; where those
// files come from decides whether a handout gives answers away:
//  - a file the stage adds or changes itself is in its folder, in lab form
//    (the TODO stubs);
//  - a file of an earlier stage that this handout also releases is never in
//    a later stage's folder: it is read from the student's own folder of that
//    stage (stage_sources.h follows `builds_on` inside the student's folder),
//    so the handout holds no solution of a stage it hands out;
//  - a file of an earlier stage this handout does not release is read from
//    the student's own folder too (Carry::Own, the default: it came with an
//    earlier handout), or put in the folder solved (Carry::Solved: for a
//    course that releases an earlier stage's solution after its deadline).
#include "stage_catalog.h"

#include <map>
#include <string>
#include <vector>

namespace raylab {

enum class Carry { Own, Solved };

struct HandoutStage {
    const StageInfo* stage = nullptr;
    std::vector<std::string> ownFiles;  // the stage's own files, lab form
    // Earlier stage id -> its files this folder holds solved (Carry::Solved).
    std::map<std::string, std::vector<std::string>> carried;
    // Earlier stage id -> its files read from the student's own folder.
    std::map<std::string, std::vector<std::string>> fromStudent;
    // Every shader file the folder holds.
    std::vector<std::string> files() const;
};

// RELEASED in course order (stage_list.h).
std::vector<HandoutStage> planHandout(const std::vector<const StageInfo*>& released, Carry carry);

// "own" or "solved"; throws Error otherwise.
Carry parseCarry(const std::string& value);

// The stage guide as this folder needs it: the guide's paragraph on what is
// provided (between "<!-- provided -->" and "<!-- /provided -->") stays when
// the folder holds every earlier file, solved; otherwise it is replaced by
// what this folder holds and which of the student's folders it reads. The
// markers themselves are removed.
//
// LABFOLDER (the handout's folder as the RayLab folder sees it, "week3/";
// empty: leave the commands alone) is added as --lab to every command of the
// guide that draws or checks the student's lab (`build/raylab check --stage
// 02` becomes `build/raylab check --stage 02 --lab week3/`): without it they
// would run the project's labs/, not the student's files.
std::string handoutGuide(const std::string& guide, const HandoutStage& plan,
                         const std::string& labFolder = "");

}  // namespace raylab
