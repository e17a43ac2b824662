#pragma once
// A shader's global `in` and `out` variables, read from its tokens
// (glsl_scan.h): what the geometry-shader emulation passes from stage to
// stage. Students need not read this file.
#include "glsl_scan.h"
#include "shader_source.h"

#include <string>
#include <vector>

namespace raylab {

// A global `in` or `out` variable.
struct GlslVarying {
    std::string type, name;
    bool array = false;
    int line = 0;  // assembled line
};

// A statement at file scope: its tokens [begin, end), `;` or `}` included.
struct GlslStatement {
    std::size_t begin = 0, end = 0;
};
std::vector<GlslStatement> fileScopeStatements(const std::vector<GlslToken>& tokens);

// The `layout( ... )` group at I, if any: returns the index after it and
// appends its words to WORDS.
std::size_t skipLayout(const std::vector<GlslToken>& tokens, std::size_t i, std::size_t end,
                       std::vector<std::string>* words = nullptr);

// Parses statement S as `[layout(...)] qualifiers STORAGE type name[, name];`
// and appends its variables to OUT; false where it is something else.
// Throws Error at SOURCE's file and line for an interface block.
bool parseVaryings(const std::vector<GlslToken>& tokens, const GlslStatement& s,
                   const std::string& storage, std::vector<GlslVarying>& out,
                   const ShaderSource& source);

// Components and base type of a float, int or uint scalar or vector.
struct BasicType {
    int components = 0;
    char base = 0;  // 'f', 'i', 'u'; 0: not a scalar or vector of these
};
BasicType basicType(const std::string& type);

}  // namespace raylab
