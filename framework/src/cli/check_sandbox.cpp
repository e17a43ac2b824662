#include "check_sandbox.h"

#include "child_process.h"
#include "error.h"
#include "gl_context.h"
#include "paths.h"
#include "stage_sources.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace raylab {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSandboxVariable = "RAYLAB_CHECK_SANDBOXED";

std::string fileText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

fs::path thisProgram() { return fs::read_symlink("/proc/self/exe"); }

// Whether the check of STAGE in LABROOT ends without a signal (a compile
// error or a failed view is fine: the compiler survived it).
bool survives(const StageInfo& stage, const fs::path& labRoot, const CheckLimits& limits,
              const fs::path& log) {
    Child probe({thisProgram().string(), "check", "--stage", stage.id, "--lab", labRoot.string(),
                 "--size", "16x12"},
                log, {limits.timeoutSeconds, limits.memoryMb});
    const ChildOutcome& o = probe.wait();
    return !o.timedOut && o.signal == 0;
}

// The student's file that makes the compiler crash: the one whose handed-out
// version, put in its place, lets the check run. Empty when no single file
// does (then none is named: a guess would mislead).
std::string crashingFile(const StageInfo& stage, const fs::path& labRoot,
                         const CheckLimits& limits) {
    const fs::path mine = labRoot / stage.id, handedOut = defaultLabRoot() / stage.id;
    std::error_code ec;
    if (fs::equivalent(mine, handedOut, ec)) return "";
    const fs::path scratch =
        fs::temp_directory_path() / ("raylab-check-crash-" + std::to_string(::getpid()));
    struct Cleanup {
        fs::path dir;
        ~Cleanup() {
            std::error_code e;
            fs::remove_all(dir, e);
        }
    } cleanup{scratch};
    for (const fs::directory_entry& entry : fs::directory_iterator(mine)) {
        const fs::path original = handedOut / entry.path().filename();
        if (!entry.is_regular_file() || !fs::is_regular_file(original)) continue;
        if (fileText(entry.path()) == fileText(original)) continue;
        fs::remove_all(scratch);
        fs::create_directories(scratch);
        fs::copy(mine, scratch / stage.id, fs::copy_options::recursive);
        fs::copy_file(original, scratch / stage.id / entry.path().filename(),
                      fs::copy_options::overwrite_existing);
        if (survives(stage, scratch, limits, scratch / "probe.log"))
            return entry.path().filename().string();
    }
    return "";
}

}  // namespace

bool insideCheckSandbox() { return std::getenv(kSandboxVariable) != nullptr; }

int runCheckInSandbox(const StageInfo& stage, const fs::path& labRoot, const CheckLimits& limits) {
    std::vector<std::string> argv = programArguments();
    argv.at(0) = thisProgram().string();
    setenv(kSandboxVariable, "1", 1);
    std::fflush(stdout);
    std::fflush(stderr);
    Child child(argv, "", {limits.timeoutSeconds, limits.memoryMb});
    const ChildOutcome o = child.wait();
    if (!o.timedOut && o.signal == 0) return o.exitCode;
    std::fflush(stdout);
    if (o.timedOut) {
        std::fprintf(stderr,
                     "raylab check: stage %s stopped after %.0f s (--timeout): an endless loop, or "
                     "a shader that takes minutes to compile\n",
                     stage.id.c_str(), limits.timeoutSeconds);
        return 2;
    }
    std::string culprit;
    if (!labRoot.empty() && (o.signal == SIGSEGV || o.signal == SIGABRT || o.signal == SIGBUS)) {
        std::fprintf(stderr,
                     "raylab check: the check crashed (%s); looking for the file that "
                     "causes it...\n",
                     o.describe().c_str());
        culprit = crashingFile(stage, labRoot, limits);
    }
    if (!culprit.empty())
        std::fprintf(stderr,
                     "raylab check: %s makes the shader compiler or driver crash (%s): with the "
                     "handed-out %s in its place the check runs\n",
                     displayPath(labRoot / stage.id / culprit).c_str(), o.describe().c_str(),
                     culprit.c_str());
    else
        std::fprintf(stderr,
                     "raylab check: stage %s crashed (%s): a crash in the shader compiler or "
                     "driver, or memory beyond --memory-mb %ld\n",
                     stage.id.c_str(), o.describe().c_str(), limits.memoryMb);
    return 2;
}

}  // namespace raylab
