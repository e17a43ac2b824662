#pragma once
// Helpers for tests that run the `raylab` binary: a scratch folder and a
// command runner that captures exit code, stdout and stderr.
#include "error.h"
#include "shader_source.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::test {

namespace fs = std::filesystem;

struct CommandResult {
    int exitCode = -1;
    std::string out;
    std::string err;
    std::string all() const { return out + err; }
};

// Runs `command` through /bin/sh (no stdin), capturing both streams.
CommandResult runCommand(const std::string& command);

// `raylab ARGS` and `raylab-labgen ARGS`, the binaries of this build (found
// through CMake, so the suite runs from any build folder).
CommandResult runRaylab(const std::string& args);
CommandResult runLabgen(const std::string& args);
fs::path raylabExe();

// The source tree and a single-quoted shell word.
fs::path sourceDir();
std::string quote(const std::string& s);

// A fresh empty folder removed when the object goes away.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const fs::path& path() const { return path_; }
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

// One headless GL context (EGL or OSMesa, whichever works), made on first
// use and current for the rest of the test program.
void ensureGlContext();

// A fully solved copy of the labs (raylab-labgen --solved) in DIR.
void writeSolvedLabs(const fs::path& dir);

// Every regular file under DIR, as paths relative to it, sorted.
std::vector<std::string> filesUnder(const fs::path& dir);

// Every student's page of the grading report in OUT (students/*/report.html),
// one after the other: where the messages and pictures are.
std::string studentPages(const fs::path& out);

// The message of the raylab::Error F throws, or "(no error)".
template <typename F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const raylab::Error& e) { return e.what(); }
    return "(no error)";
}

// Replaces the first occurrence of FROM by TO in FILE; fails the test if FROM is absent.
void replaceInFile(const fs::path& file, const std::string& from, const std::string& to);

std::string readFile(const fs::path& file);

// TEXT as if assembled from FILE: a generated `#version 330 core` line,
// then FILE's lines, each at its own origin (the rewrite tests' input).
ShaderSource assembledFrom(const std::string& file, const std::string& text);
void writeFile(const fs::path& file, const std::string& text);

// Names of the views reported as FAIL by `raylab check` output.
std::vector<std::string> failedViews(const std::string& checkOutput);

}  // namespace raylab::test
