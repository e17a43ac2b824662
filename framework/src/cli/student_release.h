#pragma once
// What a release to students holds, shared by `raylab web-bundle` (the page
// as a static folder) and `raylab student-repo` (a repository to build):
// the framework's shaders without solved variant files, the tables of the
// released stages' function checks, and the framework's C++ without the
// references (the answers in double precision) and the checks' stand-ins.
// Students need not read this file.
#include "handout.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace raylab {

// A release's options, as `raylab handout` takes them: --stages, --out
// (OUTHELP says what it may be), --carry, --course, --level.
struct ReleaseOptions {
    std::string stages, out, carry = "own", course, level = "guided";
};
void addReleaseOptions(CLI::App& cmd, ReleaseOptions& o, const std::string& outHelp);

// FROM (a file or a folder) copied to TO, TO's folder made first.
void copyTree(const std::filesystem::path& from, const std::filesystem::path& to);

// Whether students write FILE as stage STAGE reads it: its solved form (the
// newest of STAGE's chain in solution/) has regions a lab takes away.
bool studentsWrite(const std::string& stage, const std::string& file);

// framework/shaders/ into TO with the variant folders of STAGES only, and
// without the variant files that hold solved code (studentsWrite).
void copyFrameworkShaders(const std::filesystem::path& to, const std::set<std::string>& stages);

// The stages PLAN's stages build on that PLAN does not release, in course order.
std::vector<const StageInfo*> earlierStages(const std::vector<HandoutStage>& plan);

// The function tables and count tables (function_tables.h, count_tables.h) of
// PLAN's stages' checks only, as JSON.
std::string releasedFunctionTables(const std::vector<HandoutStage>& plan);

// C++ source TEXT (FILE, for messages) as a student repository holds it:
// every `#ifndef RAYLAB_REFERENCES_AS_DATA` block gone (its `#else` part
// kept), and the arguments of RAYLAB_REFERENCE, RAYLAB_REFERENCE_FUNCTION and
// RAYLAB_HARNESS_GLSL emptied (function_checks.h: the references and the
// stand-ins), which the student build (RAYLAB_REFERENCES_AS_DATA) never
// compiles anyway. Throws Error naming FILE for an unbalanced block or call.
std::string withoutReferences(const std::string& text, const std::string& file);

}  // namespace raylab
