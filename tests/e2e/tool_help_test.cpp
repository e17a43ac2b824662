// Every tool an instructor or student runs has --help (exit 0, a usage), and
// none takes an option-looking word for a path: `raylab-classgen --help` once
// made a folder named "--help" holding 30 submissions.
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

namespace {

std::string binary(const char* name) { return quote((raylabExe().parent_path() / name).string()); }
std::string script(const char* path) { return "bash " + quote((sourceDir() / path).string()); }

}  // namespace

TEST(ToolHelp, EveryToolAndCommandHasHelp) {
    std::vector<std::string> tools = {
        binary("raylab"),
        binary("raylab-labgen"),
        binary("raylab-texgen"),
        binary("raylab-classgen"),
        script("install.sh"),
        script("tools/grader/setup.sh"),
        script("tools/grader/run_autograder"),
        script("tools/check-format.sh"),
        script("tools/bench/instructions_per_frame.sh"),
        script("examples/slurm/submit.sh"),
        script("examples/slurm/local_cluster.sh"),
    };
    for (const char* command :
         {"stages", "run", "render", "rays", "trace", "grade", "demo", "bench", "check", "shader",
          "compare", "handout", "prairielearn", "gradescope", "autograder", "mutants"})
        tools.push_back(binary("raylab") + " " + command);
    ScratchDir dir;
    for (const std::string& tool : tools) {
        CommandResult r = runCommand("cd " + quote(dir.path()) + " && " + tool + " --help");
        EXPECT_EQ(r.exitCode, 0) << tool << "\n" << r.all();
        // A usage line (CLI11's), or a script's header naming itself and its arguments.
        const std::string name = fs::path(tool.substr(tool.rfind('/') + 1)).string();
        const std::string self = name.substr(0, name.find_first_of("' "));
        EXPECT_TRUE(r.all().find("sage") != std::string::npos ||
                    r.all().find(self) != std::string::npos)
            << tool << ": no usage\n"
            << r.all();
    }
    EXPECT_TRUE(filesUnder(dir.path()).empty()) << "--help wrote files";
}

TEST(ToolHelp, AnOptionLookingWordIsNeverAPath) {
    const std::vector<std::string> calls = {
        binary("raylab-classgen") + " --weird",
        binary("raylab-classgen") + " -x",
        binary("raylab-texgen") + " --weird",
        binary("raylab") + " handout --stages 01 --out --weird",
        binary("raylab") + " grade --submissions --weird --out out",
        script("examples/slurm/submit.sh") + " 2 --class out",
        script("examples/slurm/submit.sh") + " 2 class --out",
        script("examples/slurm/local_cluster.sh") + " --state true",
    };
    for (const std::string& call : calls) {
        ScratchDir dir;
        CommandResult r = runCommand("cd " + quote(dir.path()) + " && " + call);
        EXPECT_NE(r.exitCode, 0) << call << "\n" << r.all();
        EXPECT_TRUE(filesUnder(dir.path()).empty() && fs::is_empty(dir.path()))
            << call << " made something";
    }
}
