#pragma once
// A current OpenGL 3.3 core context without a window (headless rendering).
// Students need not read this file.
//
// Backends:
//  - egl:    EGL on Mesa's surfaceless platform (no display, no GPU needed),
//            falling back to the default EGL display on other drivers.
//  - osmesa: Mesa's off-screen renderer. It must run in a process whose GL
//            symbols come from libOSMesa (see osmesa_context.cpp), so choosing
//            it re-executes the program with libOSMesa preloaded.
//  - auto:   egl, or osmesa when EGL is not available.
#include <memory>
#include <string>
#include <vector>

namespace raylab {

enum class Backend { Auto, Egl, OsMesa };

Backend parseBackend(const std::string& name);  // throws Error on an unknown name

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual std::string backendName() const = 0;
};

std::unique_ptr<GlContext> createEglContext();     // throws Error when EGL is unavailable
std::unique_ptr<GlContext> createOsMesaContext();  // throws Error; requires the preloaded process

// Creates the headless context BACKEND asks for. For osmesa (chosen, or as
// the fallback of auto) this may replace the process by `argv` re-executed
// with libOSMesa preloaded and `--backend osmesa`, so call it early.
std::unique_ptr<GlContext> createHeadlessContext(Backend backend);

// main() registers its arguments here so that the process can be re-executed
// (and reports can quote the command line).
void rememberProgramArguments(int argc, char** argv);
const std::vector<std::string>& programArguments();

// True when this process's linked GL 1.1 symbols are OSMesa's (it was
// re-executed with libOSMesa preloaded).
bool inOsMesaProcess();

// Replaces this process by the remembered command with libOSMesa preloaded
// and `--backend osmesa`. Returns only by throwing Error.
[[noreturn]] void reexecWithOsMesa();

}  // namespace raylab
