// libFuzzer target: raylab::assembleShader (the #include preprocessor).
//
// The input is split on the separator line "//@@file" into up to three files,
// main.glsl (the entry), a.glsl and b.glsl, written to the process's scratch
// folder, which is the only search directory. So `#include "a.glsl"` in one
// part reaches another, and include cycles, repeats and missing files are
// exercised. assembleShader refuses names with ".." or absolute paths and
// symbolic links leading out of the search folder, and only reads regular
// files, so nothing outside the scratch folder is read (and nothing written).
#include "error.h"
#include "fuzz_support.h"
#include "shader_source.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raylab;
    static const fs::path dir = fuzz::scratchDir();
    static const char* const names[] = {"main.glsl", "a.glsl", "b.glsl"};
    static const std::string separator = "\n//@@file\n";

    std::string input(reinterpret_cast<const char*>(data), size);
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        std::size_t end = i == 2 ? std::string::npos : input.find(separator, start);
        std::string part =
            start == std::string::npos
                ? std::string()
                : input.substr(start, end == std::string::npos ? std::string::npos : end - start);
        fuzz::writeBytes(dir / names[i], reinterpret_cast<const std::uint8_t*>(part.data()),
                         part.size());
        start = end == std::string::npos ? std::string::npos : end + separator.size();
    }
    try {
        ShaderSource s = assembleShader("main.glsl", {dir}, {"RAYLAB_FUZZ 1"});
        // The origin table must cover every assembled line.
        std::size_t lines = 0;
        for (char c : s.text) lines += c == '\n';
        if (lines != s.origin.size()) __builtin_trap();
        (void)findOpenTodos(s);
        (void)mapCompilerLog("0:" + std::to_string(lines) + "(1): error: x\n", s);
        (void)mapCompilerLog(input, s);  // the input as a compiler log too
    } catch (const Error&) {
        // A message naming the file and line: the expected rejection.
    }
    return 0;
}
