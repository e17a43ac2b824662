// The table of `raylab`'s commands. A new command is a cmd_*.cpp that
// defines a Command, plus one line here.
#include "commands.h"
#include "command.h"

#include <string>

namespace raylab {

Command stagesCommand();
Command runCommand();
Command renderCommand();
Command raysCommand();
Command traceCommand();
Command gradeCommand();
Command gradeItemCommand();
Command gradeReferenceCommand();
Command demoCommand();
Command benchCommand();
Command checkCommand();

const std::vector<Command>& commandTable() {
    static const std::vector<Command> table = {
        stagesCommand(), runCommand(),   renderCommand(),    raysCommand(),
        traceCommand(),  gradeCommand(), gradeItemCommand(), gradeReferenceCommand(),
        demoCommand(),   benchCommand(), checkCommand()};
    return table;
}

namespace {
std::string gCommandLine;
}  // namespace

void rememberCommandLine(int argc, char** argv) {
    gCommandLine.clear();
    for (int i = 0; i < argc; ++i)
        gCommandLine += (i ? " " : "") + std::string(i ? argv[i] : "raylab");
}

const std::string& programCommandLine() { return gCommandLine; }

}  // namespace raylab
