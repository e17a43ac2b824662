// Child processes for grading: exit codes, signals and timeouts are told
// apart, and a timeout kills everything the child started.
#include "child_process.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <thread>

using namespace raylab;
using raylab::test::ScratchDir;
namespace fs = std::filesystem;

namespace {

ChildOutcome runToEnd(const std::string& script, const fs::path& log, double timeout = 10.0) {
    Child child({"/bin/sh", "-c", script}, log, ChildLimits{timeout, 0});
    return child.wait();
}

}  // namespace

TEST(ChildProcess, ExitCodeAndOutputGoToTheLog) {
    ScratchDir dir;
    ChildOutcome o = runToEnd("echo hello; echo oops >&2; exit 3", dir / "log.txt");
    EXPECT_FALSE(o.timedOut);
    EXPECT_EQ(o.exitCode, 3);
    EXPECT_EQ(o.signal, 0);
    EXPECT_EQ(raylab::test::readFile(dir / "log.txt"), "hello\noops\n");
    EXPECT_EQ(o.describe(), "exit code 3");
}

TEST(ChildProcess, ACrashIsASignal) {
    ScratchDir dir;
    ChildOutcome o = runToEnd("kill -SEGV $$", dir / "log.txt");
    EXPECT_EQ(o.signal, SIGSEGV);
    EXPECT_NE(o.describe().find("signal 11"), std::string::npos) << o.describe();
}

TEST(ChildProcess, ATimeoutKillsTheWholeProcessGroup) {
    ScratchDir dir;
    auto start = std::chrono::steady_clock::now();
    // The grandchild writes a file after 2 s unless it is killed with its parent.
    ChildOutcome o = runToEnd("(sleep 2; touch '" + (dir / "survived").string() + "') & sleep 30",
                              dir / "log.txt", 0.5);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(o.timedOut);
    EXPECT_LT(seconds, 5.0);
    EXPECT_NE(o.describe().find("timed out"), std::string::npos);
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
    EXPECT_FALSE(fs::exists(dir / "survived"))
        << "a process the child started outlived the timeout";
}

TEST(ChildProcess, TheMemoryLimitApplies) {
    ScratchDir dir;
    // ulimit -v reports the address-space limit in KiB.
    Child child({"/bin/sh", "-c", "ulimit -v"}, dir / "log.txt", ChildLimits{10.0, 512});
    child.wait();
    EXPECT_EQ(raylab::test::readFile(dir / "log.txt"), std::to_string(512 * 1024) + "\n");
}
