#pragma once
// `raylab check` runs its work in a child process, with the limits grading
// uses (cmd_grade.cpp): a lab whose shader crashes the driver's compiler, loops
// for ever or eats all memory gets a one-line cause instead of a dead
// terminal, and a crash names the file that causes it.
#include "gl_context.h"
#include "stage_catalog.h"

#include <filesystem>
#include <string>

namespace raylab {

struct CheckLimits {
    double timeoutSeconds = 600.0;
    long memoryMb = 0;                // address space; 0: none (a GPU driver reserves much)
    Backend backend = Backend::Auto;  // the probes that look for a crash use it too
};

// True inside the child (the work is done here, not sandboxed again).
bool insideCheckSandbox();

// Runs this command line again in a child under LIMITS and returns its exit
// code; when it dies, prints why and returns 2. LABROOT: the lab's folder
// (empty for the solution), searched for the file that makes the compiler
// crash.
int runCheckInSandbox(const StageInfo& stage, const std::filesystem::path& labRoot,
                      const CheckLimits& limits);

}  // namespace raylab
