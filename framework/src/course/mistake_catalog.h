#pragma once
// The mistakes catalogue of a stage (stage.json "mistakes": a folder of JSON
// files, one typical mistake each, written as text replacements in a solved
// lab). The tests grade every one of them; grading's class summary counts the
// submissions whose failed checks are exactly a catalogued mistake's.
//
//   {"stage": "03-shadows", "mistake": "the shadow ray starts a fixed 1e-3 off
//    the surface", "central": false, "file": "light_visibility.glsl",
//    "replace": [["from", "to"]], "caught_by": ["lightVisible"]}
//
// "central": the mistake is the stage's skill (docs/grading.md: it must cost
// at least 30 of the stage's 100 points; any other at least 5). "caught_by":
// every check it fails, and only those (the check views and function and
// count checks; seeded views are left out). "hints": every cause the check's
// hints name for it, and only those (check_report.h's causesNamed: "darker",
// "brighter", "view:NAME", "FUNCTION:DIAGNOSIS"), so that a hint that names a
// cause the mistake does not have fails the tests; [] for a mistake whose
// hints rightly say only what the pictures and cases show.
#include "stage_catalog.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

struct CatalogMistake {
    std::filesystem::path file;  // the JSON file
    std::string stage;
    std::string name;  // the file's stem: "fixed-offset"
    std::string description;
    bool central = false;
    std::string shaderFile;                                    // the lab file it changes
    std::vector<std::pair<std::string, std::string>> replace;  // text replacements, in order
    std::vector<std::string> caughtBy;                         // sorted
    std::vector<std::string> hints;                            // sorted
};

// The stage's catalogue, sorted by name; empty when its folder is missing.
// Throws Error("FILE: KEY: why") on a malformed file.
std::vector<CatalogMistake> stageMistakes(const StageInfo& stage);

}  // namespace raylab
