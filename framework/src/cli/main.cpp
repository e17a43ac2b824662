// raylab: the command line of the course framework. See `raylab --help`.
// The commands and their options are in the table of commands.cpp.
#include "command.h"
#include "commands.h"
#include "error.h"
#include "shader_program.h"

#include <CLI/CLI.hpp>

#include <cstdio>

using namespace raylab;

namespace {

// A path option's value that looks like an option ("--out --weird") is
// refused: it is a forgotten value far more often than a file named so.
void refuseOptionLookingPaths(const CLI::App& cmd) {
    static const char* const kPathOptions[] = {
        "--out",    "--submissions", "--lab",       "--labs",    "--scene",
        "--course", "--roster",      "--submitted", "--against", "--save",
        "--known",  "--root",        "--config",    "--merge",   "--heat-map"};
    for (const char* name : kPathOptions) {
        const CLI::Option* option = nullptr;
        try {
            option = cmd.get_option(name);
        } catch (const CLI::OptionNotFound&) { continue; }
        for (const std::string& value : option->results())
            if (!value.empty() && value[0] == '-')
                throw raylab::Error(std::string(name) + " '" + value +
                                    "': looks like an option, not a path (a path may not start "
                                    "with '-'; write ./" +
                                    value + " for one that does)");
    }
}

}  // namespace

int main(int argc, char** argv) {
    rememberProgramArguments(argc, argv);
    CLI::App app{
        "RayLab: build a real-time GPU ray tracer stage by stage, and grade it headlessly."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "help for every subcommand");

    std::vector<std::pair<CLI::App*, std::function<int()>>> runners;
    for (const Command& command : commandTable()) {
        CLI::App* cmd = app.add_subcommand(command.name, command.help);
        if (*command.help == '\0') cmd->group("");  // hidden
        runners.emplace_back(cmd, command.define(*cmd));
    }

    try {
        try {
            app.parse(argc, argv);
        } catch (const CLI::CallForHelp& e) {
            return app.exit(e);
        } catch (const CLI::CallForAllHelp& e) {
            return app.exit(e);
        } catch (const CLI::ParseError& e) {
            std::string help = "raylab --help";
            for (const CLI::App* sub : app.get_subcommands())
                help = "raylab " + sub->get_name() + " --help";
            std::fprintf(stderr, "raylab: error: %s (see %s)\n", e.what(), help.c_str());
            return 2;
        }
        for (const auto& [cmd, run] : runners)
            if (cmd->parsed()) {
                refuseOptionLookingPaths(*cmd);
                return run();
            }
    } catch (const ShaderError& e) {
        std::fputs(e.log().c_str(), stderr);
        std::fprintf(stderr, "raylab: error: shader does not compile: %s\n", e.what());
        return 2;
    } catch (const Error& e) {
        std::fprintf(stderr, "raylab: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: internal error: %s\n", e.what());
        return 2;
    }
    return 2;
}
