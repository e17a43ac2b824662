// `raylab handout --stages 01-03 --out DIR`: the labs students may have now.
// Each lab folder holds the solved files of the stages before it (lab 07
// has a solved stage 06), so handing out labs/ whole gives away answers;
// a handout holds the released stages only. The folder appears whole or
// not at all (written beside it, then renamed).
#include "command.h"
#include "error.h"
#include "paths.h"
#include "stage_catalog.h"
#include "stage_sources.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <unistd.h>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// "01-03" (a range within one track), "01,02,f1", "01-raycast", "all".
std::vector<const StageInfo*> releasedStages(const std::string& list) {
    std::vector<const StageInfo*> out;
    auto add = [&](const StageInfo* s) {
        if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
    };
    const std::vector<StageInfo>& all = allStages();
    if (list == "all") {
        for (const StageInfo& s : all) add(&s);
        return out;
    }
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');) {
        // A stage id has a '-' of its own ("01-raycast"): an id first, then a range.
        try {
            add(&findStage(item));
            continue;
        } catch (const Error&) {
            if (std::count(item.begin(), item.end(), '-') != 1) throw;
        }
        const std::size_t dash = item.find('-');
        const StageInfo& from = findStage(item.substr(0, dash));
        const StageInfo& to = findStage(item.substr(dash + 1));
        if (from.track != to.track)
            throw Error("--stages " + item + ": " + from.id + " and " + to.id +
                        " are on different tracks");
        auto index = [&](const StageInfo& s) { return std::size_t(&s - all.data()); };
        if (index(from) > index(to))
            throw Error("--stages " + item + ": " + from.id + " comes after " + to.id);
        for (std::size_t i = index(from); i <= index(to); ++i) add(&all[i]);
    }
    if (out.empty()) throw Error("--stages: no stage given (e.g. --stages 01-03)");
    return out;
}

std::string readme(const std::vector<const StageInfo*>& stages) {
    std::string text = "# Your labs\n\nThe stages released so far, one folder each, with its guide "
                       "(README.md):\n\n";
    for (const StageInfo* s : stages)
        text += "- [" + s->id + "](" + s->id + "/README.md): " + s->title + "\n";
    text += "\nWork in the TODO blocks of each stage's files. From the RayLab folder:\n\n"
            "    build/raylab run --stage " +
            stages.front()->number() + " --lab THIS_FOLDER\n    build/raylab check --stage " +
            stages.front()->number() +
            " --lab THIS_FOLDER\n\nLater stages arrive as new folders; copy them in beside "
            "these.\n";
    return text;
}

int cmdHandout(const std::string& list, const std::string& outDir, const std::string& labDir) {
    if (outDir.empty()) throw Error("--out DIR is required");
    const std::vector<const StageInfo*> stages = releasedStages(list);
    const fs::path labs = labDir.empty() ? defaultLabRoot() : fs::path(labDir);
    const fs::path out(outDir);
    std::error_code ec;
    for (const StageInfo* s : stages)
        if (!fs::is_directory(labs / s->id, ec))
            throw Error("lab folder " + (labs / s->id).string() + " does not exist");
    if (fs::exists(out, ec) && !(fs::is_directory(out, ec) && fs::is_empty(out, ec)))
        throw Error("--out " + outDir + ": exists and is not an empty folder (nothing written)");
    const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    if (!fs::is_directory(parent, ec))
        throw Error("--out " + outDir + ": folder " + parent.string() + " does not exist");

    const fs::path temp = parent / (out.filename().string() + ".tmp-" + std::to_string(getpid()));
    try {
        fs::create_directories(temp);
        for (const StageInfo* s : stages)
            fs::copy(labs / s->id, temp / s->id, fs::copy_options::recursive);
        FILE* f = std::fopen((temp / "README.md").c_str(), "w");
        if (!f) throw Error("cannot write " + (temp / "README.md").string());
        const std::string text = readme(stages);
        const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
        if (std::fclose(f) != 0 || !written)
            throw Error("cannot write " + (temp / "README.md").string());
        if (fs::exists(out, ec)) fs::remove(out);  // the empty folder checked above
        fs::rename(temp, out);
    } catch (const fs::filesystem_error& e) {
        fs::remove_all(temp, ec);
        throw Error("cannot write the handout: " + std::string(e.what()));
    } catch (...) {
        fs::remove_all(temp, ec);
        throw;
    }
    std::string ids;
    for (const StageInfo* s : stages) ids += (ids.empty() ? "" : ", ") + s->id;
    std::printf("raylab handout: wrote %s with %zu stage%s (%s); later stages, and their solved "
                "earlier files, are not in it\n",
                outDir.c_str(), stages.size(), stages.size() == 1 ? "" : "s", ids.c_str());
    return 0;
}

}  // namespace

Command handoutCommand() {
    return {"handout",
            "write the lab folders of the released stages only, for students (labs/ whole would "
            "give away the solved earlier stages inside later labs)",
            [](CLI::App& cmd) {
                auto stages = std::make_shared<std::string>();
                auto out = std::make_shared<std::string>();
                auto labs = std::make_shared<std::string>();
                cmd.add_option("--stages", *stages,
                               "the released stages: a range within a track (01-03, f1-f2), a "
                               "list (01,02,f1) or all")
                    ->required();
                cmd.add_option("--out", *out, "the folder to write (new, or empty)")->required();
                cmd.add_option("--labs", *labs, "the labs to copy from (default: labs/)");
                return std::function<int()>([=] { return cmdHandout(*stages, *out, *labs); });
            }};
}

}  // namespace raylab
