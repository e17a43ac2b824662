#pragma once
// The tokens of a GLSL text as its compiler would see them: comments left
// out, the preprocessor's lines read (its #defines kept, its #if/#ifdef
// branches followed) and the code of inactive branches skipped. Enough for
// rewriting a shader's declarations and calls (geometry_emulation.h), not a
// GLSL parser. Students need not read this file.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace raylab {

struct GlslToken {
    std::string text;     // an identifier, a number, or one punctuation character
    std::size_t pos = 0;  // where it starts in the text
    int line = 1;         // 1-based line of the text
    bool isWord() const;  // an identifier or keyword
};

struct GlslScan {
    std::vector<GlslToken> tokens;              // of the active code, in order
    std::map<std::string, std::string> macros;  // #define NAME VALUE, as last defined
};

// Scans TEXT. An #if whose condition is more than `defined(NAME)`, `!`,
// `&&`, `||` and whole numbers counts as true (its code is scanned).
GlslScan scanGlsl(const std::string& text);

// A function defined at file scope: `type name(...) { ... }`.
struct GlslFunction {
    std::string returnType, name;
    std::size_t nameToken = 0;        // token index of its name
    std::size_t open = 0, close = 0;  // token indices of its body's braces
};
std::vector<GlslFunction> glslFunctions(const std::vector<GlslToken>& tokens);

// The whole number NAME stands for: a literal, or a macro of one (through a
// few macros and parentheses); -1 when it is neither.
long glslWholeNumber(const std::string& name, const std::map<std::string, std::string>& macros);

}  // namespace raylab
