#include "child_process.h"

#include "error.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>

namespace raylab {

namespace {
double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
}  // namespace

std::string ChildOutcome::describe() const {
    char s[128];
    if (timedOut) std::snprintf(s, sizeof s, "timed out after %.0f s", seconds);
    else if (signal)
        std::snprintf(s, sizeof s, "killed by signal %d (%s)", signal, strsignal(signal));
    else std::snprintf(s, sizeof s, "exit code %d", exitCode);
    return s;
}

Child::Child(const std::vector<std::string>& argv, const std::filesystem::path& log,
             const ChildLimits& limits)
    : limits_(limits) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const std::string logPath = log.string();
    startSeconds_ = now();
    pid_ = fork();
    if (pid_ < 0) throw Error(std::string("cannot start a child process: ") + std::strerror(errno));
    if (pid_ == 0) {
        // The child: its own process group (so a timeout kills everything it
        // started), its output to the log, its memory capped. Only
        // async-signal-safe calls until exec.
        setpgid(0, 0);
        prctl(PR_SET_PDEATHSIG, SIGKILL);  // the grader died: so does the job
        if (getppid() == 1) _exit(126);    // it died before the line above
        int fd = logPath.empty() ? -1 : open(logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        int devNull = open("/dev/null", O_RDONLY);
        if (devNull >= 0) {
            dup2(devNull, 0);
            close(devNull);
        }
        if (limits.memoryMb > 0) {
            rlimit lim{rlim_t(limits.memoryMb) * 1024 * 1024,
                       rlim_t(limits.memoryMb) * 1024 * 1024};
            setrlimit(RLIMIT_AS, &lim);
        }
        rlimit noCore{0, 0};
        setrlimit(RLIMIT_CORE, &noCore);
        execv(args[0], args.data());
        _exit(127);
    }
    setpgid(pid_, pid_);  // also from here: no race with the child's own call
}

void Child::reap(int& status) {
    struct rusage usage {};
    wait4(pid_, &status, 0, &usage);
    outcome_.peakMb = double(usage.ru_maxrss) / 1024.0;  // Linux counts kilobytes
}

bool Child::poll() {
    if (done_) return true;
    // See whether it ended without reaping it yet: while the leader is not
    // reaped, its process-group id cannot be reused, so killing the group
    // (whatever it left behind) cannot hit a stranger.
    siginfo_t info{};
    if (waitid(P_PID, id_t(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid_) {
        kill(-pid_, SIGKILL);
        int status = 0;
        reap(status);
        done_ = true;
        outcome_.seconds = now() - startSeconds_;
        if (WIFEXITED(status)) outcome_.exitCode = WEXITSTATUS(status);
        if (WIFSIGNALED(status)) outcome_.signal = WTERMSIG(status);
        return true;
    }
    if (now() - startSeconds_ > limits_.timeoutSeconds) {
        outcome_.timedOut = true;
        kill(-pid_, SIGKILL);
        int status = 0;
        reap(status);
        outcome_.signal = SIGKILL;
        outcome_.seconds = now() - startSeconds_;
        done_ = true;
        return true;
    }
    return false;
}

const ChildOutcome& Child::wait() {
    while (!poll()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return outcome_;
}

Child::~Child() {
    if (!done_ && pid_ > 0) {
        kill(-pid_, SIGKILL);
        int status = 0;
        waitpid(pid_, &status, 0);
    }
}

std::string lastLogLine(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

}  // namespace raylab
