// The table of `raylab`'s commands. A new command is a cmd_*.cpp that
// defines a Command, plus one line here.
#include "commands.h"
#include "command.h"
#include "error.h"
#include "gl_context.h"

#include <string>

namespace raylab {

Command stagesCommand();
Command runCommand();
Command renderCommand();
Command traceCommand();
Command checkCommand();
Command shaderCommand();
Command compareCommand();
#ifndef RAYLAB_STUDENT_BUILD
Command raysCommand();
Command gradeCommand();
Command gradeItemCommand();
Command gradeReferenceCommand();
Command demoCommand();
Command benchCommand();
Command handoutCommand();
Command webBundleCommand();
Command studentRepoCommand();
Command functionTablesCommand();
Command prairieLearnCommand();
Command gradescopeCommand();
Command autograderCommand();
Command mutantsCommand();
Command similarityCommand();
#endif

#ifdef RAYLAB_STUDENT_BUILD
// `raylab demo` draws the solution: refused with that reason, not as an
// unknown command (the course's guides and web page mention it).
Command studentDemoCommand() {
    return {"demo", "(not in a student repository: the demo draws the solution)",
            [](CLI::App& cmd) {
                cmd.allow_extras();
                cmd.group("");
                return std::function<int()>([]() -> int {
                    throw Error("raylab demo draws the solution, which a student repository "
                                "does not hold; the course's web page shows the demo");
                });
            }};
}
#endif

// A student repository's build (RAYLAB_STUDENT) has the students' commands
// only: the others need the solution or the reference tracer.
const std::vector<Command>& commandTable() {
    static const std::vector<Command> table = {
#ifdef RAYLAB_STUDENT_BUILD
        stagesCommand(), runCommand(),     renderCommand(),     traceCommand(), checkCommand(),
        shaderCommand(), compareCommand(), studentDemoCommand()
#else
        stagesCommand(),
        runCommand(),
        renderCommand(),
        raysCommand(),
        traceCommand(),
        gradeCommand(),
        gradeItemCommand(),
        gradeReferenceCommand(),
        demoCommand(),
        benchCommand(),
        checkCommand(),
        shaderCommand(),
        compareCommand(),
        handoutCommand(),
        webBundleCommand(),
        studentRepoCommand(),
        functionTablesCommand(),
        prairieLearnCommand(),
        gradescopeCommand(),
        autograderCommand(),
        mutantsCommand(),
        similarityCommand()
#endif
    };
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
