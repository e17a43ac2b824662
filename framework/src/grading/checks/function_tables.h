#pragma once
// The function checks' expected values as data: every case of every check
// with the reference's value for it, and the check's harness GLSL (its
// stand-ins and helpers). The page's WebAssembly core scores against these
// (web/function_tables.json, written by `raylab function-tables`), so it
// carries no reference code and no stand-in; natively the references
// themselves run. A students' bundle (`raylab web-bundle`) holds the tables
// of its released stages' checks only.
#include "function_checks.h"
#include "stage_catalog.h"

#include <map>
#include <string>
#include <vector>

namespace raylab {

struct FunctionTable {
    std::vector<std::string> labels;  // the cases', to notice a table that drifted
    std::vector<glm::dvec4> wants;
    // The cases a float answer may call either way (FunctionCase::hitOrMiss):
    // where the reference decides it (an edge-on silhouette), a build
    // without the reference takes it from here.
    std::vector<bool> either;
    std::string prelude, helpers;  // the spec's harness GLSL (RAYLAB_HARNESS_GLSL)
};
using FunctionTables = std::map<std::string, FunctionTable>;

#ifndef RAYLAB_REFERENCES_AS_DATA
// The tables of every function check, and the count tables of every stage
// (count_tables.h), as JSON (needs the references and the harness GLSL:
// native only).
std::string functionTablesJson();
// The tables of SPECS and the count tables of STAGES only (a release).
std::string functionTablesJson(const std::vector<const FunctionSpec*>& specs,
                               const std::vector<const StageInfo*>& stages);
#endif

// Whether a file must hold every function check's table (the project's
// web/function_tables.json) or holds some (a bundle's: its stages' checks).
enum class TableCoverage { Every, Some };

// TEXT (from FILE, for messages) as tables. Throws Error naming FILE and
// the function when a table does not match today's cases (a function or
// case added, removed or renamed: write the file again), or, with
// TableCoverage::Every, when a check has no table.
FunctionTables parseFunctionTables(const std::string& text, const std::string& file,
                                   TableCoverage coverage = TableCoverage::Every);

// NAME's table in TABLES; throws Error naming FILE when there is none (a
// bundle without the stage that checks it).
const FunctionTable& tableOf(const FunctionTables& tables, const std::string& name,
                             const std::string& file);

// SPEC with its harness GLSL and its cases' `either` from TABLES (the page's
// core and a student repository, where the spec was built without them). Throws Error naming FILE
// when TABLES has no table for SPEC (a bundle without the stage that checks it).
FunctionSpec withHarnessFrom(const FunctionTables& tables, const FunctionSpec& spec,
                             const std::string& file);

// Where a build without the references (RAYLAB_REFERENCES_AS_DATA) reads
// its tables, also the file's name for messages: a student repository's
// course/function_tables.json (`raylab student-repo`), the page core's
// web/function_tables.json (a bundle's: its released stages' checks).
#ifdef RAYLAB_STUDENT_BUILD
inline constexpr const char* kTablesAsData = "course/function_tables.json";
#else
inline constexpr const char* kTablesAsData = "web/function_tables.json";
#endif
// Those tables, read once. Throws Error when the file cannot be read or
// does not match today's cases.
const FunctionTables& tablesAsData();

}  // namespace raylab
