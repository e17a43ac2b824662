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

// tools/bench/lane_occupancy.py (docs/bench/README.md's share of busy lanes):
// a 4x4 picture of one ray a pixel but one pixel of three. In blocks of 8,
// two blocks run turn 1 with every lane busy; one runs turns 2 and 3 with
// one busy lane of 8; over all turns 18 busy lanes of 32 run (56.2%).
TEST(ToolHelp, LaneOccupancyCountsTheBusyLanesOfEachTurn) {
    ScratchDir dir;
    std::string pfm = "Pf\n4 4\n-1.0\n";
    for (int i = 0; i < 16; ++i) {
        const float rays = i == 5 ? 3.0f : 1.0f;
        pfm.append(reinterpret_cast<const char*>(&rays), sizeof rays);  // little-endian here
    }
    writeFile(dir / "bounces.pfm", pfm);
    const std::string tool =
        "python3 " + quote((sourceDir() / "tools/bench/lane_occupancy.py").string());
    CommandResult r = runCommand(tool + " " + quote((dir / "bounces.pfm").string()));
    ASSERT_EQ(r.exitCode, 0) << r.all();
    for (const char* line :
         {"18 rays, at most 3 a pixel", "blocks of 4 x 2: 56.2% of the lanes run busy",
          "blocks of 2 x 4: 56.2% of the lanes run busy", "turn 1: 2 blocks, 100.0%",
          "turn 2: 1 blocks, 12.5%", "turn 3: 1 blocks, 12.5%"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
    EXPECT_EQ(runCommand(tool + " --help").exitCode, 0);
    // Not a bounces picture: one line, exit 1.
    writeFile(dir / "rgb.pfm", "PF\n1 1\n-1.0\n000000000000");
    r = runCommand(tool + " " + quote((dir / "rgb.pfm").string()));
    EXPECT_EQ(r.exitCode, 1) << r.all();
    EXPECT_NE(r.err.find("not a one-channel PFM"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}
