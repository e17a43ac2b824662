// The table of `raylab`'s commands. A new command is a cmd_*.cpp that
// defines a Command, plus one line here.
#include "commands.h"
#include "command.h"
#include "gl_context.h"

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
Command shaderCommand();
Command compareCommand();
Command handoutCommand();
Command webBundleCommand();
Command functionTablesCommand();
Command prairieLearnCommand();
Command gradescopeCommand();
Command autograderCommand();
Command mutantsCommand();
Command similarityCommand();

const std::vector<Command>& commandTable() {
    static const std::vector<Command> table = {
        stagesCommand(),       runCommand(),        renderCommand(),     raysCommand(),
        traceCommand(),        gradeCommand(),      gradeItemCommand(),  gradeReferenceCommand(),
        demoCommand(),         benchCommand(),      checkCommand(),      shaderCommand(),
        compareCommand(),      handoutCommand(),    webBundleCommand(),  functionTablesCommand(),
        prairieLearnCommand(), gradescopeCommand(), autograderCommand(), mutantsCommand(),
        similarityCommand()};
    return table;
}

std::string programCommandLine() {
    const std::vector<std::string>& args = programArguments();
    std::string line;
    for (std::size_t i = 0; i < args.size(); ++i)
        line += (i ? " " + args[i] : std::string("raylab"));
    return line;
}

}  // namespace raylab
