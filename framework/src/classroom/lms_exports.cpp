#include "lms_exports.h"

#include "atomic_file.h"
#include "error.h"
#include "grade_report.h"

#include <algorithm>
#include <cstdio>

namespace raylab {

namespace fs = std::filesystem;

std::vector<std::string> parseLmsList(const std::string& list) {
    std::vector<std::string> lmss;
    std::size_t at = 0;
    while (at <= list.size() && !list.empty()) {
        const std::size_t comma = std::min(list.find(',', at), list.size());
        std::string name = list.substr(at, comma - at);
        name.erase(0, name.find_first_not_of(' '));
        name.erase(name.find_last_not_of(' ') + 1);
        if (std::find(kLmsNames.begin(), kLmsNames.end(), name) == kLmsNames.end())
            throw Error("--lms: '" + name +
                        "' is not an LMS written here (canvas, moodle, blackboard, brightspace)");
        if (std::find(lmss.begin(), lmss.end(), name) == lmss.end()) lmss.push_back(name);
        at = comma + 1;
    }
    return lmss;
}

void checkRosterServes(const std::vector<std::string>& lmss,
                       const std::map<std::string, RosterEntry>& roster) {
    for (const std::string& lms : lmss) {
        const bool canvas = lms == "canvas", moodle = lms == "moodle",
                   blackboard = lms == "blackboard";
        const bool served = std::any_of(roster.begin(), roster.end(), [&](const auto& row) {
            const RosterEntry& e = row.second;
            if (blackboard) return !e.loginId.empty();
            return !e.id.empty() || !e.loginId.empty() || (canvas && !e.canvasId.empty()) ||
                   (moodle && !e.email.empty());
        });
        if (!served)
            throw Error("--lms " + lms + ": no roster row has an id " + lms + " matches by (" +
                        (canvas       ? "canvas_id, id or login_id"
                         : moodle     ? "id, email or login_id"
                         : blackboard ? "login_id, the username"
                                      : "id or login_id") +
                        ")");
    }
}

void writeLmsExports(const ClassResult& result, const std::vector<std::string>& lmss,
                     const LmsColumns& columns, const fs::path& outDir) {
    std::error_code ec;
    for (const std::string& lms : kLmsNames)  // never one of an earlier run
        if (std::find(lmss.begin(), lmss.end(), lms) == lmss.end())
            fs::remove(outDir / (lms + ".csv"), ec);
    for (const std::string& lms : lmss) {
        GradebookColumns c;
        c.prefix = columns.prefix;
        std::string text, how;
        if (lms == "canvas") {
            c.ids = columns.canvasAssignments;
            text = canvasCsv(result, c);
            how = "Canvas: Grades > Import";
        } else if (lms == "moodle") {
            text = moodleCsv(result, c);
            how = "Moodle: Grades > Import > CSV file; map \"ID number\" (or Email address, "
                  "Username) to the user";
        } else if (lms == "blackboard") {
            c.ids = columns.blackboardColumns;
            text = blackboardCsv(result, c);
            how = "Blackboard Learn: Grade Center > Work Offline > Upload";
        } else {
            text = brightspaceCsv(result, c);
            how = "Brightspace: Grades > Enter Grades > Import";
        }
        writeTextFileAtomic(outDir / (lms + ".csv"), text);
        std::printf("%s.csv: import it in %s\n", lms.c_str(), how.c_str());
    }
}

}  // namespace raylab
