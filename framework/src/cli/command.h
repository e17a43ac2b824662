#pragma once
// One subcommand of `raylab`: its name, its help line, its options and what
// it runs. Each cmd_*.cpp defines one; commands.cpp lists them in a table,
// and main() builds the command line from that table.
#include <CLI/CLI.hpp>

#include <functional>
#include <vector>

namespace raylab {

struct Command {
    const char* name;
    const char* help;  // empty: hidden from --help (the child-process halves of `grade`)
    // Adds the command's options to CMD and returns what runs the command
    // once the command line is parsed (it returns the exit code: 0 success,
    // 1 a check failed, 2 bad input or an error).
    std::function<std::function<int()>(CLI::App& cmd)> define;
};

// Every command, in the order `raylab --help` lists them.
const std::vector<Command>& commandTable();

}  // namespace raylab
