#pragma once
// A list of stages as every command takes it (`--stages`): one reading for
// `handout`, `grade`, `autograder`, `prairielearn` and `mutants`, so that a
// range one command accepts is never refused by another.
//   "01-03"        a range within one track (from, to, inclusive)
//   "01,02,f1"     a list; ids, numbers or both ("01-raycast", "1", "f2")
//   "01-03,f1-f2"  ranges and single stages mixed
//   "all"          every stage, both tracks
// The result is in course order (allStages()), each stage once.
#include "stage_catalog.h"

#include <string>
#include <vector>

namespace raylab {

// Throws Error("OPTION ITEM: why") naming the option (e.g. "--stages").
std::vector<const StageInfo*> parseStageList(const std::string& list,
                                             const std::string& option = "--stages");

// The same as ids ("01-raycast", ...).
std::vector<std::string> parseStageIds(const std::string& list,
                                       const std::string& option = "--stages");

}  // namespace raylab
