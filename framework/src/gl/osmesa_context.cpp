// Headless OpenGL through OSMesa. Students need not read this file.
//
// Why a process of its own: GL 1.1 functions (glClear, glDrawArrays,
// glReadPixels, ...) are linked symbols. In a normal process they resolve to
// libGL (glvnd), which silently does nothing under an OSMesa context. With
// libOSMesa preloaded they resolve to OSMesa, while Mesa's EGL and GLX still
// work - but a vendor driver's (NVIDIA) would not. So the osmesa backend
// re-executes the program with LD_PRELOAD=libOSMesa.so.8, and loads the other
// entry points into GLEW's pointers from OSMesaGetProcAddress.
#include "error.h"
#include "gl_context.h"
#include "gl_loader.h"

#define GLAPI extern
#include <GL/osmesa.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace raylab {

namespace {

constexpr const char* kOsMesaLibrary = "libOSMesa.so.8";
constexpr const char* kPreloadedMarker = "RAYLAB_OSMESA_PROCESS";

decltype(&OSMesaGetProcAddress) gGetProcAddress = nullptr;

template <typename Fn>
Fn load(void* lib, const char* name) {
    void* fn = dlsym(lib, name);
    if (!fn) throw Error(std::string("the OSMesa library lacks ") + name);
    return reinterpret_cast<Fn>(fn);
}

class OsMesaContext : public GlContext {
public:
    OsMesaContext() {
        void* lib = dlopen(kOsMesaLibrary, RTLD_NOW | RTLD_GLOBAL);
        if (!lib) throw Error(std::string("OSMesa is not available: ") + dlerror());
        auto create =
            load<decltype(&OSMesaCreateContextAttribs)>(lib, "OSMesaCreateContextAttribs");
        auto makeCurrent = load<decltype(&OSMesaMakeCurrent)>(lib, "OSMesaMakeCurrent");
        destroy_ = load<decltype(&OSMesaDestroyContext)>(lib, "OSMesaDestroyContext");
        gGetProcAddress = load<decltype(&OSMesaGetProcAddress)>(lib, "OSMesaGetProcAddress");
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  0,
                                  OSMESA_PROFILE,
                                  OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  3,
                                  OSMESA_CONTEXT_MINOR_VERSION,
                                  3,
                                  0};
        context_ = create(attributes, nullptr);
        if (!context_) throw Error("OSMesa cannot create an OpenGL 3.3 core context");
        // OSMesa wants a buffer to be current; we draw into framebuffer objects, so 1x1 is enough.
        if (!makeCurrent(context_, buffer_, GL_UNSIGNED_BYTE, 1, 1)) {
            destroy_(context_);
            throw Error("OSMesa cannot make its context current");
        }
        loadGlFrom([](const char* name) { return reinterpret_cast<void*>(gGetProcAddress(name)); });
        requireGl33();
    }
    ~OsMesaContext() override { destroy_(context_); }
    std::string backendName() const override { return "osmesa"; }

private:
    OSMesaContext context_ = nullptr;
    decltype(&OSMesaDestroyContext) destroy_ = nullptr;
    unsigned char buffer_[4] = {};
};

std::vector<std::string> gArguments;

}  // namespace

bool inOsMesaProcess() {
    // The invariant that matters: the linked GL 1.1 symbols are OSMesa's.
    Dl_info info{};
    const void* clear = reinterpret_cast<const void*>(&glClear);
    return dladdr(clear, &info) != 0 && info.dli_fname &&
           std::strstr(info.dli_fname, "OSMesa") != nullptr;
}

void reexecWithOsMesa() {
    if (const char* marker = std::getenv(kPreloadedMarker); marker && std::strcmp(marker, "1") == 0)
        throw Error(
            "the OSMesa backend needs libOSMesa preloaded, but preloading it did not take effect");
    std::string preload = kOsMesaLibrary;
    if (const char* old = std::getenv("LD_PRELOAD"); old && *old) preload += std::string(":") + old;
    setenv("LD_PRELOAD", preload.c_str(), 1);
    setenv(kPreloadedMarker, "1", 1);
    std::vector<std::string> args;
    for (std::size_t i = 0; i < gArguments.size(); ++i) {
        if (gArguments[i] == "--backend" && i + 1 < gArguments.size()) {
            ++i;
            continue;
        }
        if (gArguments[i].rfind("--backend=", 0) == 0) continue;
        args.push_back(gArguments[i]);
    }
    args.push_back("--backend");
    args.push_back("osmesa");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv("/proc/self/exe", argv.data());
    throw Error(std::string("cannot re-execute for the OSMesa backend: ") + std::strerror(errno));
}

void rememberProgramArguments(int argc, char** argv) { gArguments.assign(argv, argv + argc); }

const std::vector<std::string>& programArguments() { return gArguments; }

std::unique_ptr<GlContext> createOsMesaContext() {
    if (!inOsMesaProcess())
        throw Error("the OSMesa backend needs its own process (use --backend osmesa)");
    return std::make_unique<OsMesaContext>();
}

}  // namespace raylab
