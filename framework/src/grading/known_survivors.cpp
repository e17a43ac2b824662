#include "known_survivors.h"

#include "error.h"

#include <sstream>

namespace raylab {

namespace {
bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

std::map<std::string, KnownSurvivor> parseKnownSurvivors(const std::string& text,
                                                         const std::string& file) {
    std::map<std::string, KnownSurvivor> known;
    std::string pending;  // an id still waiting for its reason
    int pendingLine = 0;
    auto fail = [&](int n, const std::string& what) {
        throw Error(file + ":" + std::to_string(n) + ": " + what);
    };
    std::istringstream in(text);
    std::string line;
    int n = 1;
    for (; std::getline(in, line); ++n) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        const std::string trimmed = line.substr(first, line.find_last_not_of(" \t") - first + 1);
        if (first == 0) {
            if (!pending.empty()) fail(pendingLine, "no indented \"why:\" line after this mutant");
            if (known.count(trimmed)) fail(n, "this mutant is listed twice");
            pending = trimmed;
            pendingLine = n;
            continue;
        }
        if (pending.empty())
            fail(n, "an indented line must follow a mutant's line (and there is one per mutant)");
        const bool why = startsWith(trimmed, "why:");
        if (!why && !startsWith(trimmed, "not equivalent:"))
            fail(n, "the reason must start with \"why:\" (an equivalent mutant) or \"not "
                    "equivalent:\" (a gap in the checks)");
        known[pending] = {trimmed, why};
        pending.clear();
    }
    if (!pending.empty()) fail(pendingLine, "no indented \"why:\" line after this mutant");
    return known;
}

std::vector<std::string> unlistedSurvivors(const std::vector<std::string>& survivors,
                                           const std::map<std::string, KnownSurvivor>& known) {
    std::vector<std::string> unlisted;
    for (const std::string& id : survivors)
        if (!known.count(id)) unlisted.push_back(id);
    return unlisted;
}

}  // namespace raylab
