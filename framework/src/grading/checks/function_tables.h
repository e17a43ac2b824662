#pragma once
// The function checks' expected values as data: every case of every check
// with the reference's value for it. The page's WebAssembly core scores
// against these (web/function_tables.json, written by `raylab
// function-tables`), so it carries no reference code; natively the
// references themselves run.
#include "function_checks.h"

#include <map>
#include <string>
#include <vector>

namespace raylab {

struct FunctionTable {
    std::vector<std::string> labels;  // the cases', to notice a table that drifted
    std::vector<glm::dvec4> wants;
};
using FunctionTables = std::map<std::string, FunctionTable>;

// Every function check's table as JSON (needs the references: native only).
std::string functionTablesJson();

// TEXT (from FILE, for messages) as tables. Throws Error naming FILE and
// the function when a table does not match today's cases (a function or
// case added, removed or renamed: write the file again).
FunctionTables parseFunctionTables(const std::string& text, const std::string& file);

}  // namespace raylab
