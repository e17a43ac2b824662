#include "shader_source.h"

#include "shader_constants.h"

#include "error.h"
#include "paths.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>
#include <regex>
#include <sstream>
#include <unordered_set>

namespace raylab {

namespace {

const char* kGenerated = "<raylab>";

// The line parsers below are written by hand, not with std::regex: libstdc++'s
// regex matcher recurses once per character, so one long line (a long
// comment after an #include, long indentation, a long line of code) overflowed
// the stack and crashed - found by tests/fuzz/fuzz_shader_source. Each keeps
// the meaning of the regex it replaces (quoted above it), `.` included: it
// does not match '\r'.

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}
bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
std::size_t skipSpace(const std::string& s, std::size_t i) {
    while (i < s.size() && isSpace(s[i])) ++i;
    return i;
}
bool startsAt(const std::string& s, std::size_t i, const char* word) {
    return s.compare(i, std::strlen(word), word) == 0;
}
bool noCarriageReturnFrom(const std::string& s, std::size_t i) {
    return s.find('\r', std::min(i, s.size())) == std::string::npos;
}

// R"(^\s*#\s*include\s*(["<])([^">]*)[">]\s*(//.*)?$)": sets NAME.
bool parseInclude(const std::string& line, std::string& name) {
    std::size_t i = skipSpace(line, 0);
    if (i >= line.size() || line[i] != '#') return false;
    i = skipSpace(line, i + 1);
    if (!startsAt(line, i, "include")) return false;
    i = skipSpace(line, i + 7);
    if (i >= line.size() || (line[i] != '"' && line[i] != '<')) return false;
    std::size_t close = line.find_first_of("\">", i + 1);
    if (close == std::string::npos) return false;
    std::size_t rest = skipSpace(line, close + 1);
    if (rest < line.size() && !(startsAt(line, rest, "//") && noCarriageReturnFrom(line, rest)))
        return false;
    name = line.substr(i + 1, close - i - 1);
    return true;
}

// R"(^\s*#\s*version\b.*)"
bool isVersionLine(const std::string& line) {
    std::size_t i = skipSpace(line, 0);
    if (i >= line.size() || line[i] != '#') return false;
    i = skipSpace(line, i + 1);
    if (!startsAt(line, i, "version")) return false;
    i += 7;
    return (i == line.size() || !isWordChar(line[i])) && noCarriageReturnFrom(line, i);
}

// R"(^\s*//\s*(TODO\([^)]*\):?.*)$)": sets TITLE (from "TODO(" on).
bool parseTodoTitle(const std::string& line, std::string& title) {
    std::size_t i = skipSpace(line, 0);
    if (!startsAt(line, i, "//")) return false;
    i = skipSpace(line, i + 2);
    if (!startsAt(line, i, "TODO(")) return false;
    std::size_t close = line.find(')', i + 5);
    if (close == std::string::npos || !noCarriageReturnFrom(line, close)) return false;
    title = line.substr(i);
    return true;
}

// A TODO's title is its first sentence, which may go on over the comment
// lines below the TODO line (a title cut mid-sentence reads as a different
// instruction). Joined lines stop at this length.
constexpr std::size_t kLongestJoinedTitle = 400;

bool endsSentence(const std::string& text) {
    std::size_t end = text.find_last_not_of(" \t\r");
    return end != std::string::npos && std::string(".!?:").find(text[end]) != std::string::npos;
}

// The text of a line that is only a // comment (trimmed); false for any other line.
bool commentText(const std::string& line, std::string& text) {
    std::size_t i = skipSpace(line, 0);
    if (!startsAt(line, i, "//")) return false;
    i = skipSpace(line, i + 2);
    std::size_t end = line.find_last_not_of(" \t\r");
    text = end == std::string::npos || end < i ? std::string() : line.substr(i, end - i + 1);
    return true;
}

// R"(^[^/]*\blabTodo\s*\(\s*\)\s*;)" (searched): a labTodo(); call before any '/'.
bool hasStubCall(const std::string& line) {
    const std::size_t slash = line.find('/');
    for (std::size_t at = line.find("labTodo"); at != std::string::npos && at < slash;
         at = line.find("labTodo", at + 1)) {
        if (at > 0 && isWordChar(line[at - 1])) continue;
        std::size_t i = skipSpace(line, at + 7);
        if (i >= line.size() || line[i] != '(') continue;
        i = skipSpace(line, i + 1);
        if (i >= line.size() || line[i] != ')') continue;
        i = skipSpace(line, i + 1);
        if (i < line.size() && line[i] == ';') return true;
    }
    return false;
}

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
        bool escapes =
            rel.is_absolute() ||
            std::any_of(rel.begin(), rel.end(), [](const fs::path& part) { return part == ".."; });
        if (name.empty() || escapes)
            throw Error(fromFile + ":" + std::to_string(fromLine) + ": #include \"" + name +
                        "\" is not allowed: name a file inside the stage folder (no \"..\", no "
                        "absolute path)");
        for (const fs::path& dir : search) {
            fs::path candidate = dir / rel;
            std::error_code ec;
            if (!fs::is_regular_file(candidate, ec)) continue;
            // A symbolic link must not lead out of the folder either (graded
            // submissions are untrusted).
            fs::path real = fs::canonical(candidate, ec);
            fs::path base = fs::canonical(dir, ec);
            auto inside = std::mismatch(base.begin(), base.end(), real.begin(), real.end()).first ==
                          base.end();
            if (ec || !inside)
                throw Error(fromFile + ":" + std::to_string(fromLine) + ": #include \"" + name +
                            "\" leads outside " + displayPath(dir) + " (a symbolic link?)");
            return candidate;
        }
        std::string where =
            fromFile.empty() ? std::string() : fromFile + ":" + std::to_string(fromLine) + ": ";
        std::string dirs;
        for (const fs::path& dir : search) dirs += (dirs.empty() ? "" : ", ") + displayPath(dir);
        throw Error(where + "cannot find shader file \"" + name + "\" (looked in " + dirs + ")");
    }

    void include(const fs::path& file) {
        std::string key = fs::weakly_canonical(file).string();
        if (!included.insert(key).second) return;  // once per program: no include guards needed
        out.files.push_back(file);
        std::string shown = displayPath(file);
        const std::string text = readTextFile(file);
        // A NUL byte ends the text for the GL compiler ("lacks `main'"): say so.
        if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
            throw Error(
                shown + ":" +
                std::to_string(1 + std::count(text.begin(), text.begin() + long(nul), '\n')) +
                ": the file holds NUL bytes (not plain text: saved as UTF-16, or a "
                "binary file?); save it as UTF-8 text");
        std::istringstream in(text);
        std::string line, name;
        for (int n = 1; std::getline(in, line); ++n) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (parseInclude(line, name)) {
                include(resolve(name, shown, n));
            } else if (isVersionLine(line)) {
                // The framework sets the version; keep line numbers by leaving a blank line.
                emit("", shown, n);
            } else {
                emit(line, shown, n);
            }
        }
    }
};

}  // namespace

SourceLine ShaderSource::where(int assembledLine) const {
    if (assembledLine >= 1 && std::size_t(assembledLine) <= origin.size())
        return origin[std::size_t(assembledLine) - 1];
    return {kGenerated, assembledLine};
}

ShaderSource assembleShader(const std::string& entry, const std::vector<fs::path>& search,
                            const std::vector<std::string>& defines, const std::string& prelude,
                            const std::vector<std::string>& extensions) {
    Assembler a{search, {}, {}};
    a.emit(kGlslVersionLine, kGenerated, 1);
    int n = 2;
    for (const std::string& e : extensions)
        a.emit("#extension " + e + " : require", kGenerated, n++);
    for (const std::string& d : defines) a.emit("#define " + d, kGenerated, n++);
    // The pipeline stage, from the entry's extension: shared files (lab_todo.glsl)
    // offer fragment-only code such as gl_FragCoord to fragment shaders only.
    const std::string ext = fs::path(entry).extension().string();
    const char* stage = ext == ".vert"   ? "RAYLAB_VERTEX_SHADER"
                        : ext == ".geom" ? "RAYLAB_GEOMETRY_SHADER"
                        : ext == ".frag" ? "RAYLAB_FRAGMENT_SHADER"
                                         : nullptr;
    if (stage) a.emit(std::string("#define ") + stage, kGenerated, n++);
    // The constants GLSL and C++ share (shader_constants.h), then the caller's prelude.
    std::istringstream lines(shader::constantsGlsl() + prelude);
    for (std::string line; std::getline(lines, line);) a.emit(line, kGenerated, n++);
    a.include(a.resolve(entry, "", 0));
    return a.out;
}

ShaderSource asGlslEs300(ShaderSource s) {
    static const char* const kPrelude[] = {
        "#version 300 es",
        "precision highp float;",
        "precision highp int;",
        "precision highp sampler2DArray;",
        "precision highp isampler2D;",
        "precision highp samplerCube;",
        // sampler2D defaults to lowp in fragment shaders: a float texture
        // (the function checks' inputs) would be read at 10 bits.
        "precision highp sampler2D;",
    };
    const std::size_t firstLineEnd = s.text.find('\n');
    std::string text;
    for (const char* line : kPrelude) text += std::string(line) + "\n";
    s.text = text + (firstLineEnd == std::string::npos ? "" : s.text.substr(firstLineEnd + 1));
    // The version line was generated; the precision lines are too.
    std::vector<SourceLine> origin;
    for (std::size_t i = 0; i < std::size(kPrelude); ++i)
        origin.push_back({kGenerated, int(i) + 1});
    origin.insert(origin.end(), s.origin.begin() + (s.origin.empty() ? 0 : 1), s.origin.end());
    s.origin = std::move(origin);
    return s;
}

std::string mapCompilerLog(const std::string& log, const ShaderSource& source) {
    // Mesa: "0:12(5): error: ...", NVIDIA: "0(12) : error C0000: ...",
    // glslang, AMD, Intel on Windows: "ERROR: 0:12: ...".
    // Only the head of a line (at most kHead characters after the indentation)
    // goes through std::regex, which recurses per character (see above); the
    // message is the rest of the line. A line number too large for an int (on
    // which std::stoi threw out_of_range) means the line is not a reference.
    static const std::regex mesa(R"(\d+:(\d+)\((\d+)\):)");
    static const std::regex nvidia(R"(\d+\((\d+)\)\s*:)");
    static const std::regex glslang(R"((ERROR|WARNING):\s*\d+:(\d+):)");
    constexpr std::size_t kHead = 80;
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        const std::size_t start = skipSpace(line, 0);
        const std::string head = line.substr(start, kHead);
        std::smatch m;
        std::string message;
        SourceLine s;
        auto matches = [&](const std::regex& re, int lineGroup) {
            if (!std::regex_search(head, m, re, std::regex_constants::match_continuous))
                return false;
            std::string digits = m[lineGroup].str();
            digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
            if (digits.size() > 10 || (digits.size() == 10 && digits > "2147483647"))
                return false;  // over INT_MAX
            s = source.where(std::stoi(digits));
            std::size_t rest = skipSpace(line, start + std::size_t(m.length(0)));
            message = line.substr(rest);
            return noCarriageReturnFrom(line, rest);  // the regexes ended in (.*)$
        };
        if (matches(mesa, 1)) {
            line = s.file + ":" + std::to_string(s.line) + ":" + m[2].str() + ": " + message;
        } else if (matches(nvidia, 1)) {
            line = s.file + ":" + std::to_string(s.line) + ": " + message;
        } else if (matches(glslang, 2)) {
            std::string kind = m[1].str() == "ERROR" ? "error: " : "warning: ";
            line = s.file + ":" + std::to_string(s.line) + ": " + kind + message;
        }
        if (!line.empty()) out += line + "\n";
    }
    return out;
}

std::vector<OpenTodo> findOpenTodos(const ShaderSource& source) {
    std::vector<OpenTodo> todos;
    for (const fs::path& file : source.files) {
        std::string shown = displayPath(file);
        if (shown.rfind("framework/", 0) == 0) continue;
        std::istringstream in(readTextFile(file));
        std::string line, title;
        bool sentenceOpen = false;  // the title's sentence goes on in the next comment line
        for (int n = 1; std::getline(in, line); ++n) {
            if (parseTodoTitle(line, title)) {
                sentenceOpen = !endsSentence(title);
                continue;
            }
            std::string more;
            if (sentenceOpen && commentText(line, more) && !more.empty() &&
                more.rfind("Checked by", 0) != 0 && title.size() < kLongestJoinedTitle) {
                title += " " + more;
                sentenceOpen = !endsSentence(title);
                continue;
            }
            sentenceOpen = false;
            if (hasStubCall(line)) todos.push_back({shown, n, title.empty() ? "TODO" : title});
        }
    }
    return todos;
}

}  // namespace raylab
