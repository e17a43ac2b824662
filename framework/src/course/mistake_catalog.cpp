#include "mistake_catalog.h"

#include "error.h"
#include "json_reader.h"
#include "paths.h"

#include <algorithm>

namespace raylab {

namespace fs = std::filesystem;

std::vector<CatalogMistake> stageMistakes(const StageInfo& stage) {
    const fs::path dir = projectRoot() / stage.mistakes;
    std::vector<CatalogMistake> out;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return out;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        const std::string shown = displayPath(f);
        const JsonReader r{shown};
        const json doc = parseJsonFile(f, shown);
        r.allowOnly(doc, "",
                    {"stage", "mistake", "central", "file", "replace", "caught_by", "hints"});
        CatalogMistake m;
        m.file = f;
        m.name = f.stem().string();
        m.stage = r.string(r.member(doc, "mistake", "stage"), "stage");
        if (m.stage != stage.id)
            r.fail("stage", "'" + m.stage + "' in the catalogue of " + stage.id);
        m.description = r.string(r.member(doc, "mistake", "mistake"), "mistake");
        if (doc.contains("central")) {
            if (!doc["central"].is_boolean()) r.fail("central", "expected true or false");
            m.central = doc["central"].get<bool>();
        }
        m.shaderFile = r.string(r.member(doc, "mistake", "file"), "file");
        const json& replace = r.member(doc, "mistake", "replace");
        if (!replace.is_array() || replace.empty()) r.fail("replace", "expected [[from, to], ...]");
        for (std::size_t i = 0; i < replace.size(); ++i) {
            const std::string at = "replace[" + std::to_string(i) + "]";
            if (!replace[i].is_array() || replace[i].size() != 2) r.fail(at, "expected [from, to]");
            m.replace.emplace_back(r.string(replace[i][0], at), r.string(replace[i][1], at));
        }
        const json& caught = r.member(doc, "mistake", "caught_by");
        if (!caught.is_array() || caught.empty())
            r.fail("caught_by", "expected the checks it fails");
        for (const json& c : caught) m.caughtBy.push_back(r.string(c, "caught_by"));
        std::sort(m.caughtBy.begin(), m.caughtBy.end());
        const json& hints = r.member(doc, "mistake", "hints");
        if (!hints.is_array()) r.fail("hints", "expected the causes its hints name ([] for none)");
        for (const json& h : hints) m.hints.push_back(r.string(h, "hints"));
        std::sort(m.hints.begin(), m.hints.end());
        out.push_back(std::move(m));
    }
    return out;
}

}  // namespace raylab
