#include "stage_list.h"

#include "error.h"

#include <algorithm>

namespace raylab {

namespace {

std::string trimmedItem(const std::string& s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::size_t indexOf(const StageInfo& s) { return std::size_t(&s - allStages().data()); }

}  // namespace

std::vector<const StageInfo*> parseStageList(const std::string& list, const std::string& option) {
    const std::vector<StageInfo>& all = allStages();
    std::vector<bool> chosen(all.size(), false);
    if (trimmedItem(list).empty())
        throw Error(option + ": no stage given (e.g. " + option + " 01-03)");
    if (trimmedItem(list) == "all") {
        std::vector<const StageInfo*> out;
        for (const StageInfo& s : all) out.push_back(&s);
        return out;
    }
    std::size_t begin = 0;
    while (begin <= list.size()) {
        std::size_t end = list.find(',', begin);
        if (end == std::string::npos) end = list.size();
        const std::string item = trimmedItem(list.substr(begin, end - begin));
        begin = end + 1;
        if (item.empty())
            throw Error(option + " '" + list + "': an empty item (two commas, or one at an end)");
        // A stage id has a '-' of its own ("01-raycast"): an id first, then a range.
        try {
            chosen[indexOf(findStage(item))] = true;
            continue;
        } catch (const Error&) {
            if (std::count(item.begin(), item.end(), '-') != 1) {
                if (item.find('-') == std::string::npos) throw;
                throw Error(option + " " + item +
                            ": not a stage and not a range FROM-TO (e.g. 01-03)");
            }
        }
        const std::size_t dash = item.find('-');
        const StageInfo* from = nullptr;
        const StageInfo* to = nullptr;
        try {
            from = &findStage(item.substr(0, dash));
            to = &findStage(item.substr(dash + 1));
        } catch (const Error& e) { throw Error(option + " " + item + ": " + e.what()); }
        if (from->track != to->track)
            throw Error(option + " " + item + ": " + from->id + " and " + to->id +
                        " are on different tracks (give two ranges: 01-03,f1-f2)");
        if (indexOf(*from) > indexOf(*to))
            throw Error(option + " " + item + ": " + from->id + " comes after " + to->id);
        for (std::size_t i = indexOf(*from); i <= indexOf(*to); ++i) chosen[i] = true;
    }
    std::vector<const StageInfo*> out;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (chosen[i]) out.push_back(&all[i]);
    return out;
}

std::vector<std::string> parseStageIds(const std::string& list, const std::string& option) {
    std::vector<std::string> ids;
    for (const StageInfo* s : parseStageList(list, option)) ids.push_back(s->id);
    return ids;
}

}  // namespace raylab
