#pragma once
// Running an untrusted job in a child process: its own process group, a
// wall-clock timeout (the whole group is killed), an address-space limit,
// stdout and stderr to a log file (or the parent's own). Used by `raylab grade`
// and `raylab check`.
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct ChildLimits {
    double timeoutSeconds = 60.0;
    long memoryMb = 2048;  // RLIMIT_AS; 0: none
};

struct ChildOutcome {
    bool timedOut = false;
    int exitCode = -1;   // when it exited
    int signal = 0;      // when a signal ended it (SIGKILL after a timeout too)
    double seconds = 0;  // wall time
    double peakMb = 0;   // the most memory it held at once (resident set), its children's included
    std::string describe()
        const;  // "exit code 2", "killed by signal 11 (Segmentation fault)", "timed out after 20 s"
};

// The last non-empty line of a child's LOG (its error, as a rule); "" when none.
std::string lastLogLine(const std::filesystem::path& log);

class Child {
public:
    // Starts ARGV (argv[0] a path) with its output appended to LOG; an empty
    // LOG: to this process's stdout and stderr.
    Child(const std::vector<std::string>& argv, const std::filesystem::path& log,
          const ChildLimits& limits);
    // Non-blocking: true (and the outcome filled in) once the child has ended.
    // Kills the child's process group when its time is up.
    bool poll();
    // Blocks until the child has ended (or its time is up).
    const ChildOutcome& wait();
    const ChildOutcome& outcome() const { return outcome_; }
    ~Child();  // kills a child still running
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

private:
    void reap(int& status);  // waits for the ended child; its peak memory into outcome_
    int pid_ = -1;
    bool done_ = false;
    double startSeconds_ = 0;
    ChildLimits limits_;
    ChildOutcome outcome_;
};

}  // namespace raylab
