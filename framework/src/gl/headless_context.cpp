// Choosing the headless backend. Students need not read this file.
#include "error.h"
#include "gl_context.h"

#include <cstdio>

namespace raylab {

Backend parseBackend(const std::string& name) {
    if (name == "auto") return Backend::Auto;
    if (name == "egl") return Backend::Egl;
    if (name == "osmesa") return Backend::OsMesa;
    throw Error("unknown backend '" + name + "' (choose auto, egl or osmesa)");
}

std::unique_ptr<GlContext> createHeadlessContext(Backend backend) {
    if (backend == Backend::OsMesa || inOsMesaProcess()) {
        if (!inOsMesaProcess()) reexecWithOsMesa();
        return createOsMesaContext();
    }
    if (backend == Backend::Egl) return createEglContext();
    try {
        return createEglContext();
    } catch (const Error& e) {
        std::fprintf(stderr, "raylab: note: %s; using the OSMesa backend\n", e.what());
        reexecWithOsMesa();
    }
}

}  // namespace raylab
