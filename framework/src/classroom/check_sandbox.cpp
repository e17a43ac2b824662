#include "check_sandbox.h"

#include "atomic_file.h"
#include "child_process.h"
#include "error.h"
#include "gl_context.h"
#include "lab_files.h"
#include "paths.h"
#include "stage_sources.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
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
    const char* backend = limits.backend == Backend::Egl      ? "egl"
                          : limits.backend == Backend::OsMesa ? "osmesa"
                                                              : "auto";
    Child probe({thisProgram().string(), "check", "--stage", stage.id, "--lab", labRoot.string(),
                 "--size", "16x12", "--backend", backend},
                log, {limits.timeoutSeconds, limits.memoryMb});
    const ChildOutcome& o = probe.wait();
    return !o.timedOut && o.signal == 0;
}

// The student's file that makes the compiler crash: the one whose handed-out
// version, put in its place, lets the check run. Empty when no single file
// does (then none is named: a guess would mislead).
std::string crashingFile(const StageInfo& stage, const fs::path& labRoot,
                         const CheckLimits& limits) {
    const fs::path mine = labRoot / stage.id;
    // The handed-out text comes from solution/ (as labgen writes labs/), so
    // a student editing labs/ in place is compared with the lab as it was.
    // Either level's text stands in; a file as either level hands it out is
    // not the one that crashes.
    const std::map<std::string, std::string> handedOut = labFiles(stage, MarkedForm::Lab);
    const std::map<std::string, std::string> openLab =
        labFiles(stage, MarkedForm::Lab, Level::Open);
    const fs::path scratch =
        fs::temp_directory_path() / ("raylab-check-crash-" + std::to_string(::getpid()));
    struct Cleanup {
        fs::path dir;
        ~Cleanup() {
            std::error_code e;
            fs::remove_all(dir, e);
        }
    } cleanup{scratch};
    // Each probe is a short check; a few minutes at most in all.
    CheckLimits probeLimits = limits;
    probeLimits.timeoutSeconds = std::min(limits.timeoutSeconds, 60.0);
    for (const auto& [name, text] : handedOut) {
        const fs::path file = mine / name;
        if (!fs::is_regular_file(file) || fileText(file) == text ||
            fileText(file) == openLab.at(name))
            continue;
        fs::remove_all(scratch);
        fs::create_directories(scratch);
        fs::copy(mine, scratch / stage.id, fs::copy_options::recursive);
        writeTextFileAtomic(scratch / stage.id / name, text);
        if (survives(stage, scratch, probeLimits, scratch / "probe.log")) return name;
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
    else if (limits.memoryMb > 0)
        std::fprintf(stderr,
                     "raylab check: stage %s crashed (%s): a crash in the shader compiler or "
                     "driver, or memory beyond --memory-mb %ld\n",
                     stage.id.c_str(), o.describe().c_str(), limits.memoryMb);
    else
        std::fprintf(stderr,
                     "raylab check: stage %s crashed (%s): a crash in the shader compiler or "
                     "driver\n",
                     stage.id.c_str(), o.describe().c_str());
    return 2;
}

}  // namespace raylab
