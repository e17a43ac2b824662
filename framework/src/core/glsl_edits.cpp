#include "glsl_edits.h"

#include <algorithm>

namespace raylab {

std::string applyEdits(std::string text, std::vector<TextEdit> edits) {
    std::sort(edits.begin(), edits.end(),
              [](const TextEdit& a, const TextEdit& b) { return a.pos > b.pos; });
    for (const TextEdit& e : edits) text.replace(e.pos, e.length, e.text);
    return text;
}

std::string keepingLines(const std::string& source, std::size_t from, std::size_t to,
                         const std::string& text) {
    return text + std::string(std::size_t(std::count(source.begin() + long(from),
                                                     source.begin() + long(to), '\n')),
                              '\n');
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    for (std::size_t start = 0; start < text.size();) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

void appendLine(ShaderSource& s, const std::string& line, const SourceLine& from) {
    s.text += line + "\n";
    s.origin.push_back(from);
}

void appendGenerated(ShaderSource& s, const std::string& text, int* generated) {
    for (const std::string& line : splitLines(text))
        appendLine(s, line, {"<raylab>", (*generated)++});
}

}  // namespace raylab
