#include "handout.h"

#include "error.h"
#include "lab_files.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace raylab {

namespace fs = std::filesystem;

std::vector<std::string> HandoutStage::files() const {
    std::vector<std::string> out = ownFiles;
    for (const auto& [id, names] : carried) out.insert(out.end(), names.begin(), names.end());
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<HandoutStage> planHandout(const std::vector<const StageInfo*>& released, Carry carry) {
    auto isReleased = [&](const std::string& id) {
        return std::any_of(released.begin(), released.end(),
                           [&](const StageInfo* s) { return s->id == id; });
    };
    std::vector<HandoutStage> plan;
    for (const StageInfo* stage : released) {
        HandoutStage h;
        h.stage = stage;
        for (const auto& [name, file] : labFileSources(*stage)) {
            // The folder of solution/ the file comes from is its stage.
            const std::string from = file.source.parent_path().filename().string();
            if (file.own) h.ownFiles.push_back(name);
            else if (carry == Carry::Solved && !isReleased(from)) h.carried[from].push_back(name);
            else h.fromStudent[from].push_back(name);
        }
        plan.push_back(std::move(h));
    }
    return plan;
}

Carry parseCarry(const std::string& value) {
    if (value == "own") return Carry::Own;
    if (value == "solved") return Carry::Solved;
    throw Error("--carry must be own (earlier stages come from the student's own folders) or "
                "solved (earlier stages not in this handout are put in solved), not '" +
                value + "'");
}

namespace {

constexpr const char* kOpen = "<!-- provided -->";
constexpr const char* kClose = "<!-- /provided -->";

std::string codeList(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += std::string(i == 0                  ? ""
                           : i + 1 == names.size() ? " and "
                                                   : ", ") +
               "`" + names[i] + "`";
    return out;
}

// Earlier stages newest first, as the search path reads them.
std::vector<std::string> newestFirst(const std::map<std::string, std::vector<std::string>>& m,
                                     const StageInfo& stage) {
    std::vector<std::string> ids;
    for (const StageInfo* at = &stage; at;
         at = at->buildsOn.empty() ? nullptr : &findStage(at->buildsOn))
        if (m.count(at->id)) ids.push_back(at->id);
    return ids;
}

std::string providedText(const HandoutStage& h) {
    std::string text = "This folder holds the files stage " + h.stage->number() +
                       " adds: " + codeList(h.ownFiles) + ".";
    if (!h.carried.empty()) {
        text += " Provided, solved:";
        bool first = true;
        for (const std::string& id : newestFirst(h.carried, *h.stage)) {
            text += std::string(first ? " " : "; ") + "lab " + findStage(id).number() + " (" +
                    codeList(h.carried.at(id)) + ")";
            first = false;
        }
        text += ".";
    }
    if (!h.fromStudent.empty()) {
        text += " The rest is your own work from the stages it builds on, read from your "
                "folders beside this one (keep them there: a fix in an earlier stage shows here "
                "too):";
        bool first = true;
        for (const std::string& id : newestFirst(h.fromStudent, *h.stage)) {
            text += std::string(first ? " " : "; ") + "`" + id + "/` (" +
                    codeList(h.fromStudent.at(id)) + ")";
            first = false;
        }
        text += ".";
    }
    return text;
}

}  // namespace

namespace {

// Every `build/raylab COMMAND --stage X` of GUIDE that runs a lab, with
// --lab FOLDER after the stage (not where it runs the solution or names a lab).
std::string withLabOption(const std::string& guide, const std::string& folder) {
    static const std::regex command(
        R"((build/raylab (?:run|check|render|rays|trace|shader) --stage [A-Za-z0-9-]+))");
    std::istringstream in(guide);
    std::string out;
    for (std::string line; std::getline(in, line);) {
        if (line.find("--solution") == std::string::npos && line.find("--lab") == std::string::npos)
            line = std::regex_replace(line, command, "$1 --lab " + folder);
        out += line + "\n";
    }
    if (!guide.empty() && guide.back() != '\n') out.pop_back();
    return out;
}

}  // namespace

std::string handoutGuide(const std::string& original, const HandoutStage& plan,
                         const std::string& labFolder) {
    const std::string guide = labFolder.empty() ? original : withLabOption(original, labFolder);
    const std::size_t open = guide.find(kOpen);
    if (open == std::string::npos) return guide;
    const std::size_t close = guide.find(kClose, open);
    if (close == std::string::npos)
        throw Error(plan.stage->id + "/README.md: " + kOpen + " without " + kClose);
    std::string inside =
        guide.substr(open + std::string(kOpen).size(), close - open - std::string(kOpen).size());
    // The guide's own text says "every earlier file is here, solved"; when
    // some are the student's own, say what is where instead.
    if (!plan.fromStudent.empty()) inside = providedText(plan);
    // Trim the newlines the markers stood on.
    while (!inside.empty() && inside.front() == '\n') inside.erase(0, 1);
    while (!inside.empty() && inside.back() == '\n') inside.pop_back();
    std::string after = guide.substr(close + std::string(kClose).size());
    while (!after.empty() && after.front() == '\n') after.erase(0, 1);
    return guide.substr(0, open) + inside + "\n\n" + after;
}

}  // namespace raylab
