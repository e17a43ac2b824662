#include "shader_source.h"

#include "shader_constants.h"

#include "error.h"
#include "paths.h"

#include <algorithm>
#include <regex>
#include <sstream>
#include <unordered_set>

namespace raylab {

namespace {

const char* kGenerated = "<raylab>";

struct Assembler {
    const std::vector<fs::path>& search;
    ShaderSource out;
    std::unordered_set<std::string> included;  // canonical paths

    void emit(const std::string& text, const std::string& file, int line) {
        out.text += text;
        out.text += '\n';
        out.origin.push_back({file, line});
    }

    fs::path resolve(const std::string& name, const std::string& fromFile, int fromLine) {
        fs::path rel(name);
        bool escapes = rel.is_absolute() || std::any_of(rel.begin(), rel.end(), [](const fs::path& part) { return part == ".."; });
        if (name.empty() || escapes)
            throw Error(fromFile + ":" + std::to_string(fromLine) + ": #include \"" + name +
                        "\" is not allowed: name a file inside the stage folder (no \"..\", no absolute path)");
        for (const fs::path& dir : search) {
            fs::path candidate = dir / rel;
            std::error_code ec;
            if (!fs::is_regular_file(candidate, ec)) continue;
            // A symbolic link must not lead out of the folder either (graded
            // submissions are untrusted).
            fs::path real = fs::canonical(candidate, ec);
            fs::path base = fs::canonical(dir, ec);
            auto inside = std::mismatch(base.begin(), base.end(), real.begin(), real.end()).first == base.end();
            if (ec || !inside)
                throw Error(fromFile + ":" + std::to_string(fromLine) + ": #include \"" + name + "\" leads outside " + displayPath(dir) +
                            " (a symbolic link?)");
            return candidate;
        }
        std::string where = fromFile.empty() ? std::string() : fromFile + ":" + std::to_string(fromLine) + ": ";
        std::string dirs;
        for (const fs::path& dir : search) dirs += (dirs.empty() ? "" : ", ") + displayPath(dir);
        throw Error(where + "cannot find shader file \"" + name + "\" (looked in " + dirs + ")");
    }

    void include(const fs::path& file) {
        std::string key = fs::weakly_canonical(file).string();
        if (!included.insert(key).second) return;  // once per program: no include guards needed
        out.files.push_back(file);
        std::string shown = displayPath(file);
        std::istringstream in(readTextFile(file));
        static const std::regex includeRe(R"(^\s*#\s*include\s*(["<])([^">]*)[">]\s*(//.*)?$)");
        static const std::regex versionRe(R"(^\s*#\s*version\b.*)");
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::smatch m;
            if (std::regex_match(line, m, includeRe)) {
                include(resolve(m[2].str(), shown, n));
            } else if (std::regex_match(line, versionRe)) {
                // The framework sets the version; keep line numbers by leaving a blank line.
                emit("", shown, n);
            } else {
                emit(line, shown, n);
            }
        }
    }
};

} // namespace

SourceLine ShaderSource::where(int assembledLine) const {
    if (assembledLine >= 1 && std::size_t(assembledLine) <= origin.size()) return origin[std::size_t(assembledLine) - 1];
    return {kGenerated, assembledLine};
}

ShaderSource assembleShader(const std::string& entry, const std::vector<fs::path>& search,
                            const std::vector<std::string>& defines, const std::string& prelude) {
    Assembler a{search, {}, {}};
    a.emit(kGlslVersionLine, kGenerated, 1);
    int n = 2;
    for (const std::string& d : defines) a.emit("#define " + d, kGenerated, n++);
    // The constants GLSL and C++ share (shader_constants.h), then the caller's prelude.
    std::istringstream lines(shader::constantsGlsl() + prelude);
    for (std::string line; std::getline(lines, line);) a.emit(line, kGenerated, n++);
    a.include(a.resolve(entry, "", 0));
    return a.out;
}

std::string mapCompilerLog(const std::string& log, const ShaderSource& source) {
    // Mesa: "0:12(5): error: ...", NVIDIA: "0(12) : error C0000: ...",
    // glslang, AMD, Intel on Windows: "ERROR: 0:12: ...".
    static const std::regex mesa(R"(^\s*\d+:(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*\d+\((\d+)\)\s*:\s*(.*)$)");
    static const std::regex glslang(R"(^\s*(ERROR|WARNING):\s*\d+:(\d+):\s*(.*)$)");
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, mesa)) {
            SourceLine s = source.where(std::stoi(m[1]));
            line = s.file + ":" + std::to_string(s.line) + ":" + m[2].str() + ": " + m[3].str();
        } else if (std::regex_match(line, m, nvidia)) {
            SourceLine s = source.where(std::stoi(m[1]));
            line = s.file + ":" + std::to_string(s.line) + ": " + m[2].str();
        } else if (std::regex_match(line, m, glslang)) {
            SourceLine s = source.where(std::stoi(m[2]));
            std::string kind = m[1].str() == "ERROR" ? "error: " : "warning: ";
            line = s.file + ":" + std::to_string(s.line) + ": " + kind + m[3].str();
        }
        if (!line.empty()) out += line + "\n";
    }
    return out;
}

std::vector<OpenTodo> findOpenTodos(const ShaderSource& source) {
    static const std::regex todoTitle(R"(^\s*//\s*(TODO\([^)]*\):?.*)$)");
    static const std::regex stubCall(R"(^[^/]*\blabTodo\s*\(\s*\)\s*;)");
    std::vector<OpenTodo> todos;
    for (const fs::path& file : source.files) {
        std::string shown = displayPath(file);
        if (shown.rfind("framework/", 0) == 0) continue;
        std::istringstream in(readTextFile(file));
        std::string line, title;
        for (int n = 1; std::getline(in, line); ++n) {
            std::smatch m;
            if (std::regex_match(line, m, todoTitle)) title = m[1].str();
            else if (std::regex_search(line, stubCall)) todos.push_back({shown, n, title.empty() ? "TODO" : title});
        }
    }
    return todos;
}

} // namespace raylab
