#pragma once
// Assembles one GLSL shader from files: resolves `#include "name.glsl"`
// through a search path, inserts the stage's #defines after `#version`, and
// remembers where every assembled line came from, so that a driver's error
// "0:57(12): syntax error" becomes "labs/01-raycast/intersect_sphere.glsl:9:12:
// syntax error" - the file and line the student actually wrote.
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

namespace fs = std::filesystem;

struct SourceLine {
    std::string file;  // display path (see displayPath), or "<raylab>" for generated lines
    int line = 0;      // 1-based line in that file
};

struct ShaderSource {
    std::string text;                // the assembled GLSL, `#version 330 core` first
    std::vector<SourceLine> origin;  // origin[i]: where assembled line i + 1 came from
    std::vector<fs::path> files;     // every file read, entry first (hot reload watches these)

    SourceLine where(int assembledLine) const;
};

// The version every RayLab shader is compiled as (OpenGL 3.3 core).
inline constexpr const char* kGlslVersionLine = "#version 330 core";

// Reads ENTRY from the first directory of SEARCH that has it, then each
// `#include "name"` the same way (first directory wins, so a later stage can
// replace a file of an earlier one). Each file is included once. Include names
// must be plain relative names inside the search path (no "..", no absolute
// paths). Throws Error naming the including file and line on any problem.
// The shared constants (shader_constants.h) follow the defines, then PRELUDE
// (generated GLSL, e.g. a scene's constants). An entry ending in .vert, .geom
// or .frag also gets RAYLAB_VERTEX_SHADER, RAYLAB_GEOMETRY_SHADER or
// RAYLAB_FRAGMENT_SHADER defined. Each of EXTENSIONS becomes an
// `#extension NAME : require` line right after the version line (GLSL wants
// them before any code).
ShaderSource assembleShader(const std::string& entry, const std::vector<fs::path>& search,
                            const std::vector<std::string>& defines,
                            const std::string& prelude = {},
                            const std::vector<std::string>& extensions = {});

// The same shader for WebGL 2: `#version 300 es` in place of the first line
// and precision lines after it (GLSL ES has no default float precision in
// fragment shaders, nor any for some sampler types), the line mapping kept,
// so that errors still name the student's file and line. Nothing else
// changes: the stages' files are written in the subset both dialects share
// (tests/e2e/glslang_test.cpp checks it).
ShaderSource asGlslEs300(ShaderSource source);

// Rewrites the line references of a compiler or linker log (Mesa
// "0:12(5): ...", NVIDIA "0(12) : ...", glslang/AMD "ERROR: 0:12: ...") into
// "file:line[:col]: ...". Lines it does not recognise are kept as they are.
std::string mapCompilerLog(const std::string& log, const ShaderSource& source);

// A TODO block of a lab that still holds its stub: a `labTodo();` call outside
// a comment, with the title of the `// TODO(id): title` line above it: its
// first sentence, also where it goes on over the comment lines below.
struct OpenTodo {
    std::string file;
    int line = 0;
    std::string title;  // e.g. "TODO(01.a): intersect the ray with one sphere"
};

// Open TODOs in the files of SOURCE, skipping the framework's own shaders.
std::vector<OpenTodo> findOpenTodos(const ShaderSource& source);

}  // namespace raylab
