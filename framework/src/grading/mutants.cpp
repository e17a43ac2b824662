#include "mutants.h"

#include "lab_markers.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

namespace raylab {

namespace {

struct Token {
    enum Kind { Ident, Number, Punct } kind;
    std::size_t column;
    std::string text;
};

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// CODE with its comments turned into spaces (columns are kept); IN_BLOCK
// carries a /* comment over to the next line. A preprocessor line is blanked
// whole: its tokens are the framework's #defines and #includes, not code.
std::string codeOf(const std::string& line, bool& inBlock) {
    std::string code = line;
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (inBlock) {
            if (code.compare(i, 2, "*/") == 0) {
                code[i] = code[i + 1] = ' ';
                ++i;
                inBlock = false;
            } else {
                code[i] = ' ';
            }
        } else if (code.compare(i, 2, "/*") == 0) {
            code[i] = code[i + 1] = ' ';
            ++i;
            inBlock = true;
        } else if (code.compare(i, 2, "//") == 0) {
            std::fill(code.begin() + long(i), code.end(), ' ');
            break;
        }
    }
    std::size_t first = code.find_first_not_of(" \t");
    if (first != std::string::npos && code[first] == '#') code.assign(code.size(), ' ');
    return code;
}

// Trimmed, runs of white space folded to one space.
std::string folded(const std::string& code) {
    std::string out;
    for (char c : code) {
        if (c == ' ' || c == '\t' || c == '\r') {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += c;
        }
    }
    if (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

std::vector<Token> tokenize(const std::string& code) {
    static const char* const kLong[] = {
        "<<=", ">>=", "<=", ">=", "==", "!=", "&&", "||", "^^", "++", "--",
        "+=",  "-=",  "*=", "/=", "%=", "&=", "|=", "^=", "<<", ">>"};
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < code.size()) {
        const char c = code[i];
        const std::size_t start = i;
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
        } else if (isIdentStart(c)) {
            while (i < code.size() && isIdentChar(code[i])) ++i;
            tokens.push_back({Token::Ident, start, code.substr(start, i - start)});
        } else if (isDigit(c) || (c == '.' && i + 1 < code.size() && isDigit(code[i + 1]))) {
            if (c == '0' && i + 1 < code.size() && (code[i + 1] == 'x' || code[i + 1] == 'X')) {
                i += 2;
                while (i < code.size() && std::isxdigit(static_cast<unsigned char>(code[i]))) ++i;
            } else {
                while (i < code.size() && (isDigit(code[i]) || code[i] == '.')) ++i;
                if (i < code.size() && (code[i] == 'e' || code[i] == 'E')) {
                    std::size_t j = i + 1;
                    if (j < code.size() && (code[j] == '+' || code[j] == '-')) ++j;
                    if (j < code.size() && isDigit(code[j])) {
                        i = j;
                        while (i < code.size() && isDigit(code[i])) ++i;
                    }
                }
            }
            while (i < code.size() && std::isalpha(static_cast<unsigned char>(code[i]))) ++i;
            tokens.push_back({Token::Number, start, code.substr(start, i - start)});
        } else {
            std::string op(1, c);
            for (const char* l : kLong)
                if (code.compare(i, std::char_traits<char>::length(l), l) == 0) {
                    op = l;
                    break;
                }
            i += op.size();
            tokens.push_back({Token::Punct, start, op});
        }
    }
    return tokens;
}

// Whether a + or - after PREV is binary: after an operand, a closing bracket
// or a postfix ++/--. After an operator, "(", "," or "return" it is unary.
bool afterOperand(const Token* prev) {
    if (!prev) return false;
    if (prev->kind == Token::Number) return true;
    if (prev->kind == Token::Ident) return prev->text != "return" && prev->text != "case";
    return prev->text == ")" || prev->text == "]" || prev->text == "++" || prev->text == "--";
}

bool isFloatLiteral(const std::string& t) {
    if (t.size() > 1 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) return false;
    return t.find_first_of(".eEfF") != std::string::npos;
}

bool isZeroLiteral(const std::string& t) {
    if (t.size() > 1 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X'))
        return std::strtoull(t.c_str() + 2, nullptr, 16) == 0;
    return std::strtod(t.c_str(), nullptr) == 0.0;
}

// The operators' changes of one token: pairs (replacement, shown as).
struct Change {
    std::size_t column, length;
    std::string replacement, from, to;
};

void changesOf(const std::vector<Token>& tokens, std::size_t k, const Token* prev,
               std::vector<Change>& out) {
    const Token& t = tokens[k];
    const Token* next = k + 1 < tokens.size() ? &tokens[k + 1] : nullptr;
    auto swapTo = [&](const std::string& to) {
        out.push_back({t.column, t.text.size(), to, t.text, to});
    };
    if (t.kind == Token::Punct) {
        static const std::map<std::string, std::vector<std::string>> kSwaps = {
            {"<", {"<=", ">"}}, {"<=", {"<", ">="}}, {">", {">=", "<"}}, {">=", {">", "<="}},
            {"==", {"!="}},     {"!=", {"=="}},      {"*", {"/"}},       {"/", {"*"}},
            {"+=", {"-="}},     {"-=", {"+="}},      {"*=", {"/="}},     {"/=", {"*="}},
            {"&&", {"||"}},     {"||", {"&&"}}};
        auto it = kSwaps.find(t.text);
        if (it != kSwaps.end()) {
            for (const std::string& to : it->second) swapTo(to);
        } else if (t.text == "+" && afterOperand(prev)) {
            swapTo("-");
        } else if (t.text == "-") {
            if (afterOperand(prev)) swapTo("+");
            else out.push_back({t.column, 1, "", "-", ""});  // the unary minus dropped
        }
    } else if (t.kind == Token::Ident) {
        const bool call = next && next->text == "(";
        if (call && t.text == "min") swapTo("max");
        else if (call && t.text == "max") swapTo("min");
        else if (call && t.text == "normalize")
            out.push_back({t.column, t.text.size(), "", "normalize(", "("});
    } else if (!isZeroLiteral(t.text)) {
        const bool unsignedInt =
            !isFloatLiteral(t.text) && t.text.find_first_of("uU") != std::string::npos;
        swapTo(isFloatLiteral(t.text) ? "0.0" : unsignedInt ? "0u" : "0");
    }
}

}  // namespace

std::vector<Mutant> generateMutants(const std::string& file, const std::string& text) {
    const std::vector<int> solutionLines = solutionLineNumbers(text);
    const std::set<int> studentLines(solutionLines.begin(), solutionLines.end());
    std::vector<Mutant> mutants;
    bool inBlock = false;
    Token last{Token::Punct, 0, ";"};  // the token before a line's first: lines continue
    bool haveLast = false;
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::string code = codeOf(line, inBlock);
        const std::vector<Token> tokens = tokenize(code);
        if (studentLines.count(n)) {
            const std::string lineText = folded(code);
            for (std::size_t k = 0; k < tokens.size(); ++k) {
                const Token* prev = k ? &tokens[k - 1] : haveLast ? &last : nullptr;
                std::vector<Change> changes;
                changesOf(tokens, k, prev, changes);
                for (const Change& c : changes) {
                    Mutant m;
                    m.file = file;
                    m.line = n;
                    m.column = c.column;
                    m.length = c.length;
                    m.replacement = c.replacement;
                    m.lineText = lineText;
                    m.from = c.from;
                    m.to = c.to;
                    mutants.push_back(m);
                }
            }
        }
        if (!tokens.empty()) {
            last = tokens.back();
            haveLast = true;
        }
    }
    std::map<std::string, int> seen;
    for (Mutant& m : mutants) m.occurrence = ++seen[m.lineText + "\n" + m.from + "\n" + m.to];
    return mutants;
}

std::string applyMutant(const std::string& text, const Mutant& m) {
    std::size_t offset = 0;
    for (int n = 1; n < m.line; ++n) offset = text.find('\n', offset) + 1;
    std::string out = text;
    out.replace(offset + m.column, m.length, m.replacement);
    return out;
}

std::string mutantId(const Mutant& m) {
    std::string id = m.file + " | " + m.lineText + " | \"" + m.from + "\" -> \"" + m.to + "\"";
    if (m.occurrence > 1) id += " #" + std::to_string(m.occurrence);
    return id;
}

std::vector<Mutant> sampleMutants(const std::vector<Mutant>& all, std::size_t max,
                                  std::uint32_t seed) {
    if (max == 0 || max >= all.size()) return all;
    // A partial Fisher-Yates shuffle on mt19937's raw output: both are the
    // same on every standard library (std::shuffle and the distributions are
    // not), so a seed names the same sample everywhere.
    std::vector<std::size_t> index(all.size());
    std::iota(index.begin(), index.end(), std::size_t(0));
    std::mt19937 rng(seed);
    for (std::size_t i = 0; i < max; ++i)
        std::swap(index[i], index[i + std::size_t(rng()) % (index.size() - i)]);
    index.resize(max);
    std::sort(index.begin(), index.end());
    std::vector<Mutant> picked;
    for (std::size_t i : index) picked.push_back(all[i]);
    return picked;
}

}  // namespace raylab
