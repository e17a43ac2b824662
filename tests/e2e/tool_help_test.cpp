// Every tool an instructor or student runs has --help (exit 0, a usage), and
// none takes an option-looking word for a path: `raylab-classgen --help` once
// made a folder named "--help" holding 30 submissions.
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

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

// examples/slurm/submit.sh where no cluster answers: one line that says why,
// and no empty output folder left behind (sbatch stood in for by scripts:
// one that is missing, one that cannot reach a controller).
TEST(ToolHelp, SubmitWithoutAClusterSaysWhyAndLeavesNothing) {
    ScratchDir dir;
    fs::create_directories(dir / "class" / "ada");
    // A PATH of the tools the script uses, without sbatch.
    const fs::path bin = dir / "bin";
    fs::create_directories(bin);
    for (const char* tool :
         {"bash", "realpath", "mkdir", "dirname", "sed", "mktemp", "rm", "tail"}) {
        const CommandResult where = runCommand(std::string("command -v ") + tool);
        ASSERT_EQ(where.exitCode, 0) << tool;
        std::string path = where.out;
        while (!path.empty() && path.back() == '\n') path.pop_back();
        fs::create_symlink(path, bin / tool);
    }
    const std::string submit = quote((sourceDir() / "examples/slurm/submit.sh").string());
    CommandResult missing = runCommand("cd " + quote(dir.path()) + " && PATH=" + quote(bin) +
                                       " bash " + submit + " 2 class out 7");
    EXPECT_EQ(missing.exitCode, 2) << missing.all();
    EXPECT_NE(missing.err.find("sbatch is not installed here"), std::string::npos) << missing.err;
    EXPECT_FALSE(fs::exists(dir / "out"));

    writeFile(bin / "sbatch",
              "#!/bin/bash\necho 'sbatch: error: Batch job submission failed: Unable to contact "
              "slurm controller (connect failure)' >&2\nexit 1\n");
    fs::permissions(bin / "sbatch", fs::perms::owner_all);
    CommandResult down = runCommand("cd " + quote(dir.path()) + " && PATH=" + quote(bin) +
                                    " bash " + submit + " 2 class out 7");
    EXPECT_EQ(down.exitCode, 1) << down.all();
    EXPECT_NE(down.err.find("sbatch refused the grading array: sbatch: error: Batch job "
                            "submission failed: Unable to contact slurm controller"),
              std::string::npos)
        << down.err;
    EXPECT_EQ(std::count(down.err.begin(), down.err.end(), '\n'), 1) << down.err;
    EXPECT_FALSE(fs::exists(dir / "out")) << "the folder this run made is gone";
    // A folder that was there stays.
    fs::create_directories(dir / "kept");
    runCommand("cd " + quote(dir.path()) + " && PATH=" + quote(bin) + " bash " + submit +
               " 2 class kept 7");
    EXPECT_TRUE(fs::is_directory(dir / "kept"));
}
