#include "student_release.h"

#include "error.h"
#include "function_checks.h"
#include "function_tables.h"
#include "paths.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace raylab {

namespace fs = std::filesystem;

// Whether students write FILE as stage STAGE reads it: its solved form (the
// newest of STAGE's chain in solution/) has regions a lab takes away. A
// variant file standing in for such a file is that file solved; one standing
// in for a provided file (surface_at.glsl with meshes) is not.
void addReleaseOptions(CLI::App& cmd, ReleaseOptions& o, const std::string& outHelp) {
    cmd.add_option("--stages", o.stages,
                   "the released stages, as raylab handout takes them (01-03, 01,02,f1, all)")
        ->required();
    cmd.add_option("--out", o.out, outHelp)->required();
    cmd.add_option("--carry", o.carry,
                   "earlier stages this release does not hold: own or solved (as raylab handout)")
        ->capture_default_str();
    cmd.add_option("--course", o.course,
                   "a course file (docs/grading.md): the guides show its weights");
    cmd.add_option("--level", o.level, "guided or open (as raylab handout)")->capture_default_str();
}

void copyTree(const fs::path& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy(from, to, fs::copy_options::recursive);
}

bool studentsWrite(const std::string& stage, const std::string& file) {
    std::error_code ec;
    for (const StageInfo* at = &findStage(stage);; at = &findStage(at->buildsOn)) {
        if (fs::is_regular_file(at->folder() / file, ec)) {
            const std::string text = readTextFile(at->folder() / file);
            return text.find("//@solution") != std::string::npos ||
                   text.find("//@open") != std::string::npos;
        }
        if (at->buildsOn.empty()) return false;
    }
}

// framework/shaders/ with the variant folders of STAGES only, and without
// the variant files that hold solved code (studentsWrite).
void copyFrameworkShaders(const fs::path& to, const std::set<std::string>& stages) {
    const fs::path from = projectRoot() / "framework" / "shaders";
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(from)) {
        if (!e.is_regular_file()) continue;
        const fs::path rel = e.path().lexically_relative(from);
        auto part = rel.begin();
        if (part->string() == "variants") {
            if (std::distance(rel.begin(), rel.end()) != 4) continue;
            const std::string stage = std::next(part, 2)->string();
            if (!stages.count(stage) || studentsWrite(stage, rel.filename().string())) continue;
        }
        fs::create_directories((to / rel).parent_path());
        fs::copy_file(e.path(), to / rel);
    }
}

// The stages PLAN's stages build on that PLAN does not release, in course order.
std::vector<const StageInfo*> earlierStages(const std::vector<HandoutStage>& plan) {
    std::set<std::string> released, seen;
    for (const HandoutStage& h : plan) released.insert(h.stage->id);
    for (const HandoutStage& h : plan)
        for (const StageInfo* at = h.stage; !at->buildsOn.empty();) {
            at = &findStage(at->buildsOn);
            if (!released.count(at->id)) seen.insert(at->id);
        }
    std::vector<const StageInfo*> out;
    for (const StageInfo& s : allStages())
        if (seen.count(s.id)) out.push_back(&s);
    return out;
}

// web/function_tables.json with the tables of PLAN's stages' checks only.
std::string releasedFunctionTables(const std::vector<HandoutStage>& plan) {
    std::vector<const FunctionSpec*> specs;
    std::vector<const StageInfo*> stages;
    for (const HandoutStage& h : plan) {
        stages.push_back(h.stage);
        for (const FunctionSpec* spec : functionSpecsFor(*h.stage))
            if (std::find(specs.begin(), specs.end(), spec) == specs.end()) specs.push_back(spec);
    }
    return functionTablesJson(specs, stages);
}

namespace {

// The index after the call whose "(" is at OPEN in TEXT: strings, raw
// strings, characters and comments skipped; npos when it never closes.
std::size_t afterCall(const std::string& text, std::size_t open, std::size_t* comma) {
    int depth = 0;
    for (std::size_t i = open; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            i = text.find('\n', i);
            if (i == std::string::npos) return i;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            i = text.find("*/", i + 2);
            if (i == std::string::npos) return i;
            ++i;
        } else if (c == 'R' && i + 1 < text.size() && text[i + 1] == '"') {
            const std::size_t paren = text.find('(', i + 2);
            if (paren == std::string::npos) return paren;
            const std::string close = ")" + text.substr(i + 2, paren - i - 2) + "\"";
            i = text.find(close, paren);
            if (i == std::string::npos) return i;
            i += close.size() - 1;
        } else if (c == '"' || c == '\'') {
            for (++i; i < text.size() && text[i] != c; ++i)
                if (text[i] == '\\') ++i;
        } else if (c == '(' || c == '[' || c == '{') {
            ++depth;
        } else if (c == ')' || c == ']' || c == '}') {
            if (--depth == 0) return i + 1;
        } else if (c == ',' && depth == 1 && comma && *comma == std::string::npos) {
            *comma = i;
        }
    }
    return std::string::npos;
}

// TEXT without its `#ifndef RAYLAB_REFERENCES_AS_DATA` blocks (their `#else` kept).
std::string withoutReferenceBlocks(const std::string& text, const std::string& file) {
    std::istringstream in(text);
    std::string out, line;
    int depth = 0;  // #if nesting inside a block
    bool inside = false, keeping = true;
    int n = 0, openedAt = 0;
    auto directive = [](const std::string& l) {
        const std::size_t a = l.find_first_not_of(" \t");
        return a == std::string::npos || l[a] != '#' ? std::string() : l.substr(a);
    };
    while (std::getline(in, line)) {
        ++n;
        const std::string d = directive(line);
        if (!inside) {
            if (d.rfind("#ifndef RAYLAB_REFERENCES_AS_DATA", 0) == 0) {
                inside = true, keeping = false, depth = 0, openedAt = n;
                continue;
            }
            out += line + "\n";
            continue;
        }
        if (d.rfind("#if", 0) == 0) ++depth;
        else if (d.rfind("#endif", 0) == 0 && depth-- == 0) {
            inside = false, keeping = true;
            continue;
        } else if (d.rfind("#else", 0) == 0 && depth == 0) {
            keeping = true;
            continue;
        }
        if (keeping) out += line + "\n";
    }
    if (inside)
        throw Error(file + ":" + std::to_string(openedAt) +
                    ": #ifndef RAYLAB_REFERENCES_AS_DATA without its #endif");
    return out;
}

}  // namespace

std::string withoutReferences(const std::string& text, const std::string& file) {
    std::string s = withoutReferenceBlocks(text, file);
    struct Macro {
        const char* name;
        bool keepFirst;           // RAYLAB_REFERENCE(spec, ...): the spec stays
        const char* replacement;  // what the rest becomes
    };
    static const Macro kMacros[] = {{"RAYLAB_REFERENCE_FUNCTION", false, "nullptr"},
                                    {"RAYLAB_REFERENCE", true, "nullptr"},
                                    {"RAYLAB_HARNESS_GLSL", false, "\"\""}};
    std::string out;
    std::size_t i = 0;
    while (i < s.size()) {
        // The next call of a macro, outside a comment and a #define.
        std::size_t at = std::string::npos;
        const Macro* macro = nullptr;
        for (const Macro& m : kMacros) {
            for (std::size_t from = i;;) {
                const std::size_t k = s.find(std::string(m.name) + "(", from);
                if (k == std::string::npos || k >= at) break;
                const std::size_t lineStart = s.rfind('\n', k) + 1;  // npos + 1 = 0
                const std::string before = s.substr(lineStart, k - lineStart);
                const bool skipped =
                    before.find("//") != std::string::npos ||
                    before.find("#define") != std::string::npos ||
                    (k > 0 &&
                     (std::isalnum(static_cast<unsigned char>(s[k - 1])) || s[k - 1] == '_'));
                if (!skipped) {
                    at = k, macro = &m;
                    break;
                }
                from = k + 1;
            }
        }
        if (!macro) {
            out += s.substr(i);
            break;
        }
        const std::size_t open = at + std::string(macro->name).size();
        std::size_t comma = std::string::npos;
        const std::size_t end = afterCall(s, open, &comma);
        if (end == std::string::npos) {
            const long line = std::count(s.begin(), s.begin() + long(at), '\n') + 1;
            throw Error(file + ":" + std::to_string(line) + ": " + macro->name +
                        "( without its closing parenthesis");
        }
        out += s.substr(i, open + 1 - i);
        if (macro->keepFirst && comma != std::string::npos)
            out += s.substr(open + 1, comma - open - 1) + ", ";
        out += std::string(macro->replacement) + ")";
        i = end;
    }
    return out;
}

}  // namespace raylab
