#include "earlier_stage_checks.h"

#include "paths.h"

#include <regex>
#include <sstream>

namespace raylab {

namespace fs = std::filesystem;

std::string fileDefining(const std::string& name, const std::vector<fs::path>& files) {
    // "bool findClosest(Ray ray, out Hit hit)": a type, the name, "(" at the
    // start of a line (a call is never preceded by a bare type there).
    const std::regex definition("^\\s*[A-Za-z_]\\w*\\s+" + name + "\\s*\\(");
    for (const fs::path& file : files) {
        std::istringstream in(readTextFile(file));
        for (std::string line; std::getline(in, line);)
            if (std::regex_search(line, definition)) return displayPath(file);
    }
    return "";
}

std::vector<EarlierFunctionCheck> earlierFunctionChecks(const StageInfo& stage,
                                                        const StageSources& sources) {
    std::vector<EarlierFunctionCheck> out;
    for (const OwnEarlierStage& earlier : ownEarlierStagesRead(stage, sources)) {
        const StageInfo& e = findStage(earlier.id);
        std::vector<fs::path> files;
        for (const std::string& f : earlier.files) files.push_back(sources.labRoot / e.id / f);
        for (const FunctionSpec* spec : functionSpecsFor(e)) {
            const std::string file = fileDefining(spec->name, files);
            if (file.empty()) continue;
            std::string inLab;
            for (const fs::path& f : files)
                if (displayPath(f) == file) inLab = e.id + "/" + f.filename().string();
            out.push_back({&e, spec, file, inLab});
        }
    }
    return out;
}

std::string formatEarlierFailures(const StageInfo& stage,
                                  const std::vector<EarlierFailure>& failures,
                                  const std::string& labArg) {
    if (failures.empty()) return "";
    std::string out;
    for (const EarlierFailure& f : failures) {
        const FunctionOutcome& o = f.outcome;
        out += "raylab check: stage " + stage.number() + " reads your own " + f.check.file +
               ", and its " + f.check.spec->name + " fails stage " + f.check.stage->number() +
               "'s check (" + std::to_string(o.passed) + "/" + std::to_string(o.total) +
               " cases; first failure: " + o.firstFailure + ")\n";
    }
    const EarlierFailure& first = failures.front();
    out += "  fix it there first (raylab check --stage " + first.check.stage->number() + labArg +
           "): the checks of stage " + stage.number() +
           " below go wrong with it, and the grader takes stage " + first.check.stage->number() +
           " solved when it grades " + stage.number() + "\n";
    return out;
}

std::string earlierFailuresNote(const std::vector<EarlierFailure>& failures) {
    if (failures.empty()) return "";
    std::string files;
    for (const EarlierFailure& f : failures)
        files += (files.empty() ? "" : "; ") + f.check.inLab + " (" + f.check.spec->name + ", " +
                 std::to_string(f.outcome.passed) + "/" + std::to_string(f.outcome.total) +
                 " cases)";
    return "graded with the earlier stages solved, as the course grades each stage on its own; "
           "this stage reads your own " +
           files + ", which fail" + (failures.size() == 1 ? "s" : "") +
           " there: the slip costs points in its own stage only, fix it there";
}

}  // namespace raylab
