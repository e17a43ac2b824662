#include "glsl_scan.h"

#include <cctype>

namespace raylab {

namespace {

bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// One #if level: whether its code is scanned, and whether a branch was taken.
struct Branch {
    bool outerActive = true, taken = false, active = true;
};

// A preprocessor condition, as far as this scanner evaluates one: tokens of
// `defined NAME`, `defined(NAME)`, `!`, `&&`, `||`, whole numbers and macros
// of whole numbers. Anything else counts as true.
class Condition {
public:
    Condition(const std::string& text, const std::map<std::string, std::string>& macros)
        : macros_(macros) {
        for (std::size_t i = 0; i < text.size();) {
            if (std::isspace(static_cast<unsigned char>(text[i]))) {
                ++i;
            } else if (wordChar(text[i])) {
                std::size_t j = i;
                while (j < text.size() && wordChar(text[j])) ++j;
                tokens_.push_back(text.substr(i, j - i));
                i = j;
            } else if (text.compare(i, 2, "&&") == 0 || text.compare(i, 2, "||") == 0) {
                tokens_.push_back(text.substr(i, 2));
                i += 2;
            } else {
                tokens_.push_back(std::string(1, text[i++]));
            }
        }
    }
    bool value() {
        const bool v = orExpr();
        return ok_ && at_ == tokens_.size() ? v : true;
    }

private:
    const std::string& peek() const {
        static const std::string end;
        return at_ < tokens_.size() ? tokens_[at_] : end;
    }
    bool orExpr() {
        bool v = andExpr();
        while (peek() == "||") {
            ++at_;
            v = andExpr() || v;
        }
        return v;
    }
    bool andExpr() {
        bool v = unary();
        while (peek() == "&&") {
            ++at_;
            v = unary() && v;
        }
        return v;
    }
    bool unary() {
        const std::string t = peek();
        if (t == "!") {
            ++at_;
            return !unary();
        }
        if (t == "(") {
            ++at_;
            const bool v = orExpr();
            if (peek() != ")") ok_ = false;
            ++at_;
            return v;
        }
        if (t == "defined") {
            ++at_;
            const bool paren = peek() == "(";
            if (paren) ++at_;
            const bool v = macros_.count(peek()) > 0;
            ++at_;
            if (paren) {
                if (peek() != ")") ok_ = false;
                ++at_;
            }
            return v;
        }
        ++at_;
        const long n = glslWholeNumber(t, macros_);
        if (n < 0 && !(std::isalpha(static_cast<unsigned char>(t.empty() ? '0' : t[0])) ||
                       (!t.empty() && t[0] == '_'))) {
            ok_ = false;
            return true;
        }
        return n > 0;  // an undefined name is 0, as the preprocessor says
    }

    const std::map<std::string, std::string>& macros_;
    std::vector<std::string> tokens_;
    std::size_t at_ = 0;
    bool ok_ = true;
};

// Past the /* ... */ comment at I (to the end of TEXT if it is not
// closed), counting its newlines into LINE.
std::size_t skipBlockComment(const std::string& text, std::size_t i, int& line) {
    const std::size_t end = text.find("*/", i + 2);
    const std::size_t stop = end == std::string::npos ? text.size() : end + 2;
    for (; i < stop; ++i)
        if (text[i] == '\n') ++line;
    return stop;
}

std::string trim(const std::string& s) {
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

}  // namespace

bool GlslToken::isWord() const {
    return !text.empty() && (std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_');
}

long glslWholeNumber(const std::string& name, const std::map<std::string, std::string>& macros) {
    std::string t = trim(name);
    for (int depth = 0; depth < 8; ++depth) {
        while (t.size() >= 2 && t.front() == '(' && t.back() == ')')
            t = trim(t.substr(1, t.size() - 2));
        if (!t.empty() && t.size() < 10 && t.find_first_not_of("0123456789") == std::string::npos)
            return std::stol(t);
        const auto m = macros.find(t);
        if (m == macros.end()) return -1;
        t = trim(m->second);
    }
    return -1;
}

GlslScan scanGlsl(const std::string& text) {
    GlslScan out;
    std::vector<Branch> branches;
    auto active = [&] { return branches.empty() || branches.back().active; };
    int line = 1;
    bool lineStart = true;  // only spaces so far on this line
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
            lineStart = true;
            continue;
        }
        if (text.compare(i, 2, "//") == 0) {
            while (i < text.size() && text[i] != '\n') ++i;
            continue;
        }
        if (text.compare(i, 2, "/*") == 0) {
            i = skipBlockComment(text, i, line);
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        if (c == '#' && lineStart) {
            // The directive's logical line, comments left out.
            std::string directive;
            ++i;
            while (i < text.size() && text[i] != '\n') {
                if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
                    i += 2;
                    ++line;
                    continue;
                }
                if (text.compare(i, 2, "//") == 0) {
                    while (i < text.size() && text[i] != '\n') ++i;
                    break;
                }
                if (text.compare(i, 2, "/*") == 0) {
                    i = skipBlockComment(text, i, line);
                    directive += ' ';
                    continue;
                }
                directive += text[i++];
            }
            directive = trim(directive);
            std::size_t nameEnd = 0;
            while (nameEnd < directive.size() && wordChar(directive[nameEnd])) ++nameEnd;
            const std::string name = directive.substr(0, nameEnd);
            const std::string rest = trim(directive.substr(nameEnd));
            if (name == "ifdef" || name == "ifndef" || name == "if") {
                Branch b;
                b.outerActive = active();
                bool v = name == "if" ? Condition(rest, out.macros).value()
                                      : (out.macros.count(rest) > 0) == (name == "ifdef");
                b.active = b.outerActive && v;
                b.taken = v;
                branches.push_back(b);
            } else if ((name == "elif" || name == "else") && !branches.empty()) {
                Branch& b = branches.back();
                const bool v = !b.taken && (name == "else" || Condition(rest, out.macros).value());
                b.active = b.outerActive && v;
                b.taken = b.taken || v;
            } else if (name == "endif" && !branches.empty()) {
                branches.pop_back();
            } else if (name == "define" && active()) {
                std::size_t k = 0;
                while (k < rest.size() && wordChar(rest[k])) ++k;
                out.macros[rest.substr(0, k)] = trim(rest.substr(k));
            } else if (name == "undef" && active()) {
                out.macros.erase(rest);
            }
            continue;
        }
        lineStart = false;
        std::size_t j = i + 1;
        if (wordChar(c)) {
            // A word or a number (with its fraction, exponent and suffix).
            while (j < text.size() &&
                   (wordChar(text[j]) ||
                    (text[j] == '.' && std::isdigit(static_cast<unsigned char>(c)))))
                ++j;
        }
        if (active()) out.tokens.push_back({text.substr(i, j - i), i, line});
        i = j;
    }
    return out;
}

std::vector<GlslFunction> glslFunctions(const std::vector<GlslToken>& t) {
    std::vector<GlslFunction> out;
    int depth = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i].text == "{") {
            // `type name ( ... ) {` at file scope (not a struct's or a block's).
            if (depth++ == 0 && i > 0 && t[i - 1].text == ")") {
                std::size_t open = i - 1;
                int nest = 0;
                for (; open > 0; --open) {
                    if (t[open].text == ")") ++nest;
                    else if (t[open].text == "(" && --nest == 0) break;
                }
                if (open >= 2 && t[open - 1].isWord() && t[open - 2].isWord())
                    out.push_back({t[open - 2].text, t[open - 1].text, open - 1, i, i});
            }
        } else if (t[i].text == "}" && depth > 0 && --depth == 0 && !out.empty() &&
                   out.back().close == out.back().open) {
            out.back().close = i;
        }
    }
    return out;
}

}  // namespace raylab
