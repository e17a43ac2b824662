#pragma once
// A report per section (the roster's `section` column), next to the whole
// class's: OUT/sections/<section>/ holds the section's report.html and
// summary.csv, and its students' folders and the reference pictures as
// links to the class's files (copies where the file system has no hard
// links), so that the folder alone can be handed to the section's TA.
// Anonymised runs keep the sections: the pseudonyms carry them, the key
// stays with the instructor.
#include "grade_report.h"
#include "grade_result.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

// Writes every section's folder (none when no student has a section) and
// returns (section, "sections/<folder>/report.html") for the class page.
std::vector<std::pair<std::string, std::string>>
writeSectionReports(const ClassResult& result, const std::filesystem::path& outDir);

// A section's name as a folder name: letters, digits, '.', '-' and '_'
// kept, anything else '_' ("Mon 10:00" -> "Mon_10_00").
std::string sectionFolderName(const std::string& section);

}  // namespace raylab
