// `raylab function-tables`: the function checks' expected values as data
// (grading/checks/function_tables.h), for the page's core, which carries no
// reference code. `--out web/function_tables.json` writes the file the
// project ships; `--check FILE` says whether FILE is still what the
// references give (a test keeps web/function_tables.json current).
#include "atomic_file.h"
#include "command.h"
#include "error.h"
#include "function_tables.h"
#include "paths.h"

#include <cstdio>

namespace raylab {

namespace {

int cmdFunctionTables(const std::string& out, const std::string& check) {
    const std::string text = functionTablesJson();
    if (!check.empty()) {
        const std::string shipped = readTextFile(check);
        parseFunctionTables(shipped, check);  // a one-line cause when it no longer fits
        if (shipped != text) {
            std::fprintf(stderr,
                         "raylab function-tables: %s differs from what the references give "
                         "(write it again: raylab function-tables --out %s)\n",
                         check.c_str(), check.c_str());
            return 1;
        }
        std::printf("raylab function-tables: %s is current\n", check.c_str());
        return 0;
    }
    if (out.empty()) {
        std::fputs(text.c_str(), stdout);
        return 0;
    }
    writeTextFileAtomic(out, text);
    std::printf("raylab function-tables: wrote %s\n", out.c_str());
    return 0;
}

}  // namespace

Command functionTablesCommand() {
    return {"function-tables",
            "print or write the function checks' expected values as data (the page's core "
            "scores against web/function_tables.json)",
            [](CLI::App& cmd) {
                auto out = std::make_shared<std::string>();
                auto check = std::make_shared<std::string>();
                auto* o = cmd.add_option("--out", *out, "write the tables to FILE");
                cmd.add_option("--check", *check,
                               "exit 1 when FILE is not what the references give")
                    ->excludes(o);
                return std::function<int()>([=] { return cmdFunctionTables(*out, *check); });
            }};
}

}  // namespace raylab
